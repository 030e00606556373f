#include "io/coco_common.hpp"

#include <gtest/gtest.h>

namespace silva::io {
namespace {

// Known answers worked from COCO's RLE string format: 5 bits per character plus 48, bit 0x20 = more
// characters follow, from the fourth count on the difference to the count two before.
TEST(CocoRle, StringOfCountsMatchesTheFormat) {
  EXPECT_EQ(rle_string({1, 2, 1}), "121");
  EXPECT_EQ(rle_string({3, 2, 10, 1}), "32:O");  // 1 - 2 = -1: one character 31 + 48
  EXPECT_EQ(rle_string({100}), "T3");             // 100 = 4 + 32 * 3: 4 | 0x20 then 3
  EXPECT_EQ(rle_string({}), "");
}

TEST(CocoRle, RunsAreColumnMajorAndStartWithZeros) {
  // 3 rows x 2 columns; column-major order: 1 1 0 | 0 2 1.
  cv::Mat labels = (cv::Mat_<uint16_t>(3, 2) << 1, 0, 1, 2, 0, 1);
  const auto runs = column_major_runs(labels, 2);
  EXPECT_EQ(runs[0], (std::vector<uint32_t>{0, 2, 3, 1}));
  EXPECT_EQ(runs[1], (std::vector<uint32_t>{4, 1, 1}));
}

TEST(CocoRle, AValueAbsentFromTheImageIsAllZeros) {
  cv::Mat labels = (cv::Mat_<uint16_t>(2, 2) << 1, 1, 1, 1);
  const auto runs = column_major_runs(labels, 2);
  EXPECT_EQ(runs[0], (std::vector<uint32_t>{0, 4}));
  EXPECT_EQ(runs[1], (std::vector<uint32_t>{4}));
}

}  // namespace
}  // namespace silva::io
