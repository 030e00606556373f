// Known answers for camera rays through pixel centres.
#include "raycast/camera_rays.hpp"

#include <gtest/gtest.h>

#include <set>

#include "test_meshes.hpp"

namespace silva::raycast {
namespace {

TEST(CameraRays, BlockOrderCoversEveryPixelOnceInBlocksOfSixteen) {
  const int w = 10, h = 7;
  const std::vector<uint32_t> order = block_order(w, h);
  ASSERT_EQ(order.size(), size_t(w * h));
  EXPECT_EQ(std::set<uint32_t>(order.begin(), order.end()).size(), order.size());
  // The first 16 are the 4x4 block at the origin; the third block of the first row is 2 pixels wide.
  for (int k = 0; k < 16; ++k) EXPECT_EQ(order[size_t(k)], uint32_t((k / 4) * w + k % 4));
  EXPECT_EQ(order[32], 8u);
  EXPECT_EQ(order[33], 9u);
  EXPECT_EQ(order[34], uint32_t(w + 8));
}

TEST(CameraRays, DepthOfAPlaneIsItsAnalyticZThroughEachPixelCentre) {
  // A camera 2 m above the ground looking straight down: every pixel sees the ground at z = 2.
  const Mesh ground = test::square(100.0f);
  RayScene scene;
  const RayInstance inst{&ground, Affine3f::Identity(), 0};
  scene.add_group(0, std::span<const RayInstance>(&inst, 1));
  scene.commit();
  Camera cam = Camera::from_fov(13, 9, 90.0, 0.05, 150.0);
  cam.camera_to_world = pose_from_angles(Vec3d(0.5, -0.25, 2.0), 0.0, -90.0, 0.0);
  const std::vector<uint32_t> pixels = block_order(cam.width, cam.height);
  std::vector<RayHit> hits(pixels.size());
  cast_pixels(scene, cam, pixels, hits);
  for (size_t k = 0; k < pixels.size(); ++k) {
    ASSERT_TRUE(hits[k].hit);
    EXPECT_NEAR(hits[k].t, 2.0f, 1e-5f);
    // The hit lies on the ray K^-1 (u + 0.5, v + 0.5, 1) scaled to z = 2.
    const int u = int(pixels[k] % 13), v = int(pixels[k] / 13);
    const Vec3d want = cam.position() + 2.0 * cam.ray_direction(u, v);
    EXPECT_NEAR((hits[k].position.cast<double>() - want).norm(), 0.0, 1e-4) << u << "," << v;
  }
  // Beyond `far` nothing is hit.
  cam.far = 1.5;
  cast_pixels(scene, cam, pixels, hits);
  for (const RayHit& h : hits) EXPECT_FALSE(h.hit);
}

}  // namespace
}  // namespace silva::raycast
