#include <gtest/gtest.h>

#include "render/lighting.hpp"
#include "render/shade.hpp"
#include "render/shadow_lookup.hpp"
#include "shading_scene.hpp"

namespace silva::render {
namespace {

const Vec3f kUp(0, 0, 1);

TEST(ShadingShadow, OccludedPointIsDarkAndOpenPointIsLit) {
  const ShadowMap map = test::plane_shadow_map(Vec3d(0, 0, 1), 100, 0.1, 1.0, 2.0);
  EXPECT_EQ(shadow_visibility(map, Vec3f(0, 0, 0), kUp, kUp), 0.0f);
  EXPECT_EQ(shadow_visibility(map, Vec3f(3, 3, 0), kUp, kUp), 1.0f);
  // Outside the map: lit.
  EXPECT_EQ(shadow_visibility(map, Vec3f(30, 0, 0), kUp, kUp), 1.0f);
}

TEST(ShadingShadow, NoAcneOnALitPlaneUnderAGrazingSun) {
  for (double elevation_deg : {10.0, 35.0, 70.0}) {
    const double el = elevation_deg * 3.14159265358979 / 180.0;
    const Vec3d to_sun(std::cos(el) * 0.6, std::cos(el) * 0.8, std::sin(el));
    const ShadowMap map = test::plane_shadow_map(to_sun, 256, 0.1);
    for (int k = 0; k < 200; ++k) {
      const Vec3f p(float(-3.0 + 0.031 * k), float(2.0 - 0.017 * k), 0.0f);
      ASSERT_EQ(shadow_visibility(map, p, kUp, to_sun.cast<float>()), 1.0f) << elevation_deg << " deg, point " << k;
    }
  }
}

TEST(ShadingShadow, ShadowStaysAttachedToTheOccluderEdge) {
  // A thin slab 0.3 m above the ground: points under it, up to its edge, are shadowed
  // (a large bias would detach the shadow: peter-panning).
  const ShadowMap map = test::plane_shadow_map(Vec3d(0, 0, 1), 100, 0.1, 1.0, 0.3);
  EXPECT_EQ(shadow_visibility(map, Vec3f(0.5f, 0.5f, 0), kUp, kUp), 0.0f);
  EXPECT_LT(shadow_visibility(map, Vec3f(0.95f, 0, 0), kUp, kUp), 0.5f);
  EXPECT_EQ(shadow_visibility(map, Vec3f(1.25f, 0, 0), kUp, kUp), 1.0f);
}

TEST(ShadingShadow, ShadowedPixelIsDarkerThanTheSameMaterialLit) {
  LightingPreset preset = preset_day();
  preset.sun_elevation_deg = 90;
  const Camera cam = test::test_camera(32, 24, 60);  // looking steeply down at the ground near the origin
  const GBuffer g = test::plane_gbuffer(cam, Material::Trail);
  const ShadowMap open = test::plane_shadow_map(Vec3d(0, 0, 1), 200, 0.1);
  const ShadowMap blocked = test::plane_shadow_map(Vec3d(0, 0, 1), 200, 0.1, 50.0, 5.0);
  std::vector<uint8_t> lit, dark;
  shade_rgb({g, cam, preset, &open, 3, "random", 0, 0.0f}, lit);
  shade_rgb({g, cam, preset, &blocked, 3, "random", 0, 0.0f}, dark);
  const size_t centre = (size_t(12) * 32 + 16) * 3;
  ASSERT_GT(g.depth[centre / 3], 0.0f);
  for (int c = 0; c < 3; ++c) EXPECT_LT(int(dark[centre + c]) + 20, int(lit[centre + c])) << "channel " << c;
}

}  // namespace
}  // namespace silva::render
