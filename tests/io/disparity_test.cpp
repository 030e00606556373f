#include "io/disparity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace silva::io {
namespace {

TEST(Disparity, IsFocalTimesBaselineOverDepthInKittiUnits) {
  const double fx = 500, baseline = 0.12;  // f·B = 60 px·m
  const std::vector<float> depth = {1.0f, 2.0f, 7.5f, 30.0f};
  const std::vector<uint16_t> d = kitti_disparity(depth, fx, baseline);
  ASSERT_EQ(d.size(), depth.size());
  EXPECT_EQ(d[0], 15360);  // 60 px · 256
  EXPECT_EQ(d[1], 7680);   // 30 px
  EXPECT_EQ(d[2], 2048);   // 8 px
  EXPECT_EQ(d[3], 512);    // 2 px
}

TEST(Disparity, NoSurfaceAndUnrepresentableValuesAreInvalid) {
  const double fx = 500, baseline = 0.12;
  // sky (0), closer than f·B / 256 (disparity over 255.996 px), and so far that it rounds below 1/256 px
  const std::vector<float> depth = {0.0f, 0.2f, 1e6f, 60.0f / 255.0f};
  const std::vector<uint16_t> d = kitti_disparity(depth, fx, baseline);
  EXPECT_EQ(d[0], 0);
  EXPECT_EQ(d[1], 0);
  EXPECT_EQ(d[2], 0);
  EXPECT_EQ(d[3], 65280);  // 255 px still fits
}

}  // namespace
}  // namespace silva::io
