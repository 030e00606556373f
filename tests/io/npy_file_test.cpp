#include "io/npy_file.hpp"

#include <gtest/gtest.h>

#include <string>

namespace silva::io {
namespace {

TEST(NpyFile, HeaderIsNumpysVersionOneFormPaddedTo64Bytes) {
  const size_t shape[2] = {2, 3};
  const uint8_t data[6] = {1, 2, 3, 4, 5, 6};
  const std::vector<uint8_t> file = npy_file("|u1", shape, data);
  ASSERT_EQ(file.size(), 128u + 6u);  // 10 bytes of magic and length + a 60-character dict do not fit in 64
  EXPECT_EQ(std::string(file.begin() + 1, file.begin() + 6), "NUMPY");
  EXPECT_EQ(file[0], 0x93);
  EXPECT_EQ(file[6], 1);
  EXPECT_EQ(file[8] + 256 * file[9], 128 - 10);
  const std::string header(file.begin() + 10, file.begin() + 128);
  EXPECT_EQ(header.rfind("{'descr': '|u1', 'fortran_order': False, 'shape': (2, 3), }", 0), 0u) << header;
  EXPECT_EQ(header.back(), '\n');
  EXPECT_EQ(file[128], 1);
  EXPECT_EQ(file.back(), 6);
}

TEST(NpyFile, OneDimensionalShapeKeepsItsComma) {
  const size_t shape[1] = {4};
  const uint8_t data[16] = {};
  const std::vector<uint8_t> file = npy_file("<f4", shape, data);
  EXPECT_EQ(file.size(), 128u + 16u);
  EXPECT_NE(std::string(file.begin(), file.begin() + 128).find("'shape': (4,), }"), std::string::npos);
}

}  // namespace
}  // namespace silva::io
