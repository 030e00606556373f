#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "highway_targets.hpp"
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

TEST(ShadingShadow, TheShadowOfOneTexelIsRoundNotSquare) {
  // One occluding texel 2 m above the ground, the sun overhead: at the same distance from it the ground
  // is as dark along an axis as along a diagonal (a separable tent's square contours darken the diagonal).
  const ShadowMap map = test::plane_shadow_map(Vec3d(0, 0, 1), 101, 0.1, 0.03, 2.0);
  int partial = 0;
  for (double r : {0.05, 0.08, 0.11, 0.14, 0.17}) {
    const float d = float(r / std::sqrt(2.0));
    const float axis = shadow_visibility(map, Vec3f(float(r), 0, 0), kUp, kUp);
    const float diagonal = shadow_visibility(map, Vec3f(d, d, 0), kUp, kUp);
    partial += axis < 1.0f && diagonal < 1.0f;
    EXPECT_NEAR(axis, diagonal, 0.03f) << r;
  }
  EXPECT_GE(partial, 4);
  EXPECT_EQ(shadow_visibility(map, Vec3f(0.16f, 0.16f, 0), kUp, kUp), 1.0f);  // beyond the radius on the diagonal
}

TEST(ShadingShadow, RowLookupIsIdenticalOnEveryHighwayTargetAndMatchesSinglePoints) {
  const ShadowMap map = test::plane_shadow_map(Vec3d(0.3, 0.2, 1).normalized(), 100, 0.1, 1.0, 2.0);
  const Vec3f to_sun = Vec3d(0.3, 0.2, 1).normalized().cast<float>();
  std::vector<Vec3f> positions, normals;
  for (int i = 0; i < 41; ++i) {  // a line across the shadow edge, plus points outside the map
    positions.emplace_back(float(i) * 0.07f - 1.4f, 0.013f * float(i), 0.0f);
    normals.push_back(i % 3 == 0 ? Vec3f(0, 0, -1) : Vec3f(0.1f, 0, 1).normalized());
  }
  positions.emplace_back(40, 0, 0);
  normals.push_back(kUp);
  const std::vector<int64_t> targets = test::highway_targets();
  ASSERT_GE(targets.size(), 2u);
  const std::vector<float> reference = [&] {
    const test::PinnedTarget portable(targets.back());
    std::vector<float> r(positions.size());
    shadow_visibility_row(map, positions.data(), normals.data(), positions.size(), to_sun, r.data());
    return r;
  }();
  EXPECT_EQ(reference.back(), 1.0f);  // outside the map
  int penumbra = 0;
  for (float r : reference) penumbra += r > 0.0f && r < 1.0f;
  EXPECT_GT(penumbra, 0);
  for (int64_t target : targets) {
    const test::PinnedTarget pinned(target);
    ASSERT_EQ(shadow_simd_target(), target);
    SCOPED_TRACE(hwy::TargetName(target));
    std::vector<float> row(positions.size());
    shadow_visibility_row(map, positions.data(), normals.data(), positions.size(), to_sun, row.data());
    for (size_t i = 0; i < positions.size(); ++i) {
      EXPECT_EQ(row[i], reference[i]) << i;
      EXPECT_EQ(shadow_visibility(map, positions[i], normals[i], to_sun), reference[i]) << i;
    }
  }
}

TEST(ShadingShadow, ShadowedPixelIsDarkerThanTheSameMaterialLit) {
  LightingPreset preset = preset_day();
  preset.sun_elevation_deg = 90;
  const Camera cam = test::test_camera(32, 24, 60);  // looking steeply down at the ground near the origin
  const GBuffer g = test::plane_gbuffer(cam, Material::Trail);
  const ShadowMap open = test::plane_shadow_map(Vec3d(0, 0, 1), 200, 0.1);
  const ShadowMap blocked = test::plane_shadow_map(Vec3d(0, 0, 1), 200, 0.1, 50.0, 5.0);
  std::vector<uint8_t> lit, dark;
  shade_rgb({g, cam, preset, &open, 3, "random", 0, {}}, lit);
  shade_rgb({g, cam, preset, &blocked, 3, "random", 0, {}}, dark);
  const size_t centre = (size_t(12) * 32 + 16) * 3;
  ASSERT_GT(g.depth[centre / 3], 0.0f);
  for (int c = 0; c < 3; ++c) EXPECT_LT(int(dark[centre + c]) + 20, int(lit[centre + c])) << "channel " << c;
}

}  // namespace
}  // namespace silva::render
