#include "render/view_directions.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <vector>

#include "highway_targets.hpp"

namespace silva::render {
namespace {

TEST(ViewDirections, MatchTheCamerasRayDirectionsOnEveryHighwayTarget) {
  // Widths that end inside a vector; poses turned about every axis; off-centre principal points.
  const struct {
    int width, height;
    double fov, yaw, pitch, roll;
  } views[] = {{101, 37, 90, 0, 0, 0}, {640, 360, 70, 123.4, -12.5, 3.0}, {97, 61, 120, -45, 80, -20}};
  for (const auto& view : views) {
    Camera camera = Camera::from_fov(view.width, view.height, view.fov, 0.05, 150);
    camera.camera_to_world = pose_from_angles(Vec3d(10, -4, 2), view.yaw, view.pitch, view.roll);
    camera.cx += 3.25;
    camera.cy -= 1.5;
    SCOPED_TRACE(view.width);
    for (int64_t target : test::highway_targets()) {
      SCOPED_TRACE(hwy::TargetName(target));
      const test::PinnedTarget pin(target);
      std::vector<Vec3f> row(size_t(camera.width));
      size_t differing = 0;
      for (int v = 0; v < camera.height; ++v) {
        view_directions_row(camera, v, row.data());
        for (int u = 0; u < camera.width; ++u) {
          const Vec3f want = camera.ray_direction(u, v).normalized().cast<float>();
          for (int c = 0; c < 3; ++c)
            differing += std::bit_cast<uint32_t>(row[size_t(u)][c]) != std::bit_cast<uint32_t>(want[c]) ? 1 : 0;
        }
      }
      EXPECT_EQ(differing, 0u);
    }
  }
}

}  // namespace
}  // namespace silva::render
