#include <gtest/gtest.h>

#include "systems/capture_pipeline.hpp"

namespace silva::world {
namespace {

int for_image(int w, int h) { return shadow_resolution(Camera::from_fov(w, h, 90.0, 0.05, 150.0)); }

TEST(ShadowResolution, FollowsTheLongerImageSideWithinLimits) {
  EXPECT_EQ(for_image(1920, 1080), 2048);
  EXPECT_EQ(for_image(2560, 1440), 2048);  // capped
  EXPECT_EQ(for_image(1280, 720), 2048);
  EXPECT_EQ(for_image(1024, 768), 1024);   // exact power of two
  EXPECT_EQ(for_image(720, 480), 1024);
  EXPECT_EQ(for_image(480, 640), 1024);    // portrait: the longer side counts
  EXPECT_EQ(for_image(64, 48), 256);       // floor
}

}  // namespace
}  // namespace silva::world
