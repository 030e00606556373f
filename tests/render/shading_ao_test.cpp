#include <gtest/gtest.h>

#include "render/shade_ao.hpp"
#include "shading_scene.hpp"

namespace silva::render {
namespace {

TEST(ShadingAo, OpenPlaneIsUnoccludedAndTheFootOfAWallIsOccluded) {
  const Camera cam = test::test_camera(320, 200, 20);
  const GBuffer open = test::plane_gbuffer(cam, Material::Ground);
  const GBuffer walled = test::plane_gbuffer(cam, Material::Ground, 6.0);
  int occluded_feet = 0, feet = 0;
  for (int v = 0; v < cam.height; ++v) {
    for (int u = 0; u < cam.width; ++u) {
      const size_t i = size_t(v) * size_t(cam.width) + size_t(u);
      if (open.depth[i] > 0) {
        EXPECT_EQ(screen_space_ao(open, cam, u, v), 1.0f) << u << "," << v;
      }
      const Vec3f& p = walled.position[i];
      if (walled.depth[i] > 0 && walled.normal[i].z() > 0.5f && p.x() > 5.7f) {
        ++feet;
        occluded_feet += screen_space_ao(walled, cam, u, v) < 0.9f ? 1 : 0;
      }
    }
  }
  ASSERT_GT(feet, 0);
  EXPECT_GT(occluded_feet, feet / 2);
}

}  // namespace
}  // namespace silva::render
