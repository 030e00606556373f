#include "render/shadow_plan.hpp"

#include <gtest/gtest.h>

#include <random>

#include "render/shadow_pass.hpp"

namespace silva::render {
namespace {

int for_image(int w, int h) { return shadow_resolution(Camera::from_fov(w, h, 90.0, 0.05, 150.0)); }

/// A 1920 x 1080 camera at `position` with the given yaw and pitch (degrees).
Camera view(const Vec3d& position, double yaw, double pitch, int w = 1920, int h = 1080) {
  Camera c = Camera::from_fov(w, h, 90.0, 0.05, 150.0);
  c.camera_to_world = pose_from_angles(position, yaw, pitch, 0.0);
  return c;
}

bool contains(const AABB& b, const Vec3d& p) {
  return (p.cast<float>().array() >= b.min.array()).all() && (p.cast<float>().array() <= b.max.array()).all();
}

TEST(ShadowPlan, ResolutionFollowsTheLongerImageSideWithinLimits) {
  EXPECT_EQ(for_image(1920, 1080), 2048);
  EXPECT_EQ(for_image(2560, 1440), 2048);  // capped
  EXPECT_EQ(for_image(1280, 720), 2048);
  EXPECT_EQ(for_image(1024, 768), 1024);   // exact power of two
  EXPECT_EQ(for_image(720, 480), 1024);
  EXPECT_EQ(for_image(480, 640), 1024);    // portrait: the longer side counts
  EXPECT_EQ(for_image(64, 48), 256);       // floor
}

TEST(ShadowPlan, FittedBoxHoldsEveryVisiblePointOfTheFullBox) {
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < 60; ++k) {
    const bool aerial = k % 3 == 0;
    const Camera cam = view(Vec3d(40 * unit(gen) - 20, 40 * unit(gen) - 20, aerial ? 15.0 : 1.5), 360 * unit(gen),
                            aerial ? -30 - 50 * unit(gen) : 20 * unit(gen) - 10);
    const AABB full = shadow_box(cam, 0.0f, 1.5);
    const AABB fitted = fit_shadow_box(full, cam);
    EXPECT_TRUE((fitted.min.array() >= full.min.array()).all() && (fitted.max.array() <= full.max.array()).all());
    int inside = 0;
    for (int s = 0; s < 2000; ++s) {
      const Vec3d p = cam.position() + 150.0 * unit(gen) *
                                           cam.ray_direction(int(unit(gen) * cam.width), int(unit(gen) * cam.height));
      if (!contains(full, p)) continue;
      ++inside;
      ASSERT_TRUE(contains(fitted, p)) << "camera " << k << " point " << p.transpose();
    }
    EXPECT_GT(inside, 100);
  }
}

TEST(ShadowPlan, LevelGroundViewCoversAboutHalfTheBox) {
  for (double yaw : {0.0, 45.0, 100.0}) {
    const Camera cam = view(Vec3d(3, -2, 1.5), yaw, 0.0);
    const AABB full = shadow_box(cam, 0.0f, 1.5);
    const AABB fitted = fit_shadow_box(full, cam);
    const double ratio = double(fitted.size().x() * fitted.size().y()) / double(full.size().x() * full.size().y());
    EXPECT_LT(ratio, 0.56) << yaw;  // 90 degrees of view: a half (facing an axis) or a quarter (a diagonal)
    EXPECT_GT(ratio, 0.2) << yaw;
    EXPECT_EQ(fitted.min.z(), full.min.z());
    EXPECT_EQ(fitted.max.z(), full.max.z());
  }
}

TEST(ShadowPlan, KeepsTheFullBoxTexelSizeWithFewerTexels) {
  const float ground_z = 0.7f;
  const double max_elevation = 6.0;
  const Vec3d to_sun = Vec3d(0.4, -0.3, 0.8).normalized();
  for (double yaw : {0.0, 30.0, 135.0, 250.0}) {
    const Camera cam = view(Vec3d(5, 5, 2), yaw, -5.0);
    const ShadowPlan plan = plan_shadow({&cam, 1}, ground_z, max_elevation, to_sun);
    const AABB full = shadow_box(cam, ground_z, max_elevation);
    const double full_texel = shadow_map_frame(to_sun, full, shadow_resolution(cam)).texel_size;
    const double texel = shadow_map_frame(to_sun, plan.region, plan.resolution).texel_size;
    EXPECT_LE(texel, full_texel * (1 + 1e-9)) << yaw;
    EXPECT_GT(texel, 0.9 * full_texel) << yaw;  // not finer than needed
    EXPECT_LT(plan.resolution, shadow_resolution(cam)) << yaw;
  }
}

}  // namespace
}  // namespace silva::render
