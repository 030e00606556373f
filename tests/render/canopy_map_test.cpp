#include "render/canopy_map.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <limits>

#include "render/shadow_pass.hpp"

namespace silva::render {
namespace {

/// Canopy top height of the test scene's wood (m): everything at world x < 0 is covered at this height.
constexpr double kTop = 10.0;

/// A top-down depth map of flat ground at z = 0 with a closed canopy at z = kTop over x < 0, drawn as
/// the renderer would (light looking down), 0.125 m texels over 80 x 80 m.
ShadowMap wood_edge() {
  AABB region;
  region.extend(Vec3f(-40.0f, -40.0f, -5.0f));
  region.extend(Vec3f(40.0f, 40.0f, 20.0f));
  ShadowMap map = shadow_map_frame(Vec3d::UnitZ(), region, 640);
  const Mat4d to_world = map.world_to_light.inverse();
  map.depth.assign(size_t(map.width) * size_t(map.height), std::numeric_limits<float>::infinity());
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      const Eigen::Vector4d p = to_world * Eigen::Vector4d(map.origin_x + (x + 0.5) * map.texel_size,
                                                           map.origin_y + (y + 0.5) * map.texel_size, 0.0, 1.0);
      const Vec3d top(p.x(), p.y(), p.x() < 0.0 ? kTop : 0.0);
      map.depth[size_t(y) * size_t(map.width) + size_t(x)] = float(map.world_to_light.block<1, 3>(2, 0).dot(top));
    }
  return map;
}

/// canopy_share_row at one point.
float share_at(const CanopyMap& map, const Vec3f& p) {
  float out = -1.0f;
  canopy_share_row(map, &p, 1, &out);
  return out;
}

TEST(CanopyMap, KnownAnswersAtAWoodEdge) {
  const CanopyMap map = build_canopy_map(wood_edge(), [](double, double) { return 0.0; });
  EXPECT_NEAR(share_at(map, Vec3f(-20.0f, 3.0f, 0.0f)), 1.0f, 1e-6f);  // deep in the wood: no sky
  EXPECT_NEAR(share_at(map, Vec3f(20.0f, 3.0f, 0.0f)), 0.0f, 1e-6f);   // in the open
  EXPECT_NEAR(share_at(map, Vec3f(-20.0f, 3.0f, 3.0f)), 1.0f, 1e-6f);  // under the canopy, above the ground
  EXPECT_NEAR(share_at(map, Vec3f(-20.0f, 3.0f, 25.0f)), 0.0f, 1e-6f); // above the canopy
  // At the canopy's own height a point is half below it: gap 0.5, share 1 - 0.5^1.5.
  EXPECT_NEAR(share_at(map, Vec3f(-20.0f, 3.0f, float(kTop))), 1.0f - std::pow(0.5f, 1.5f), 1e-3f);
  // At the edge both blurred covers, the crowns near and the stand, are a half (the boxes are symmetric
  // about it): gap (1 - 0.5)(1 - 0.5).
  EXPECT_NEAR(share_at(map, Vec3f(0.0f, 3.0f, 0.0f)), 1.0f - std::pow(0.25f, 1.5f), 0.05f);
  // 10 m into the open no crown is near, but the stand's box reaches 5 m into the wood: a sixth of it.
  EXPECT_NEAR(share_at(map, Vec3f(10.0f, 3.0f, 0.0f)), 1.0f - std::pow(5.0f / 6.0f, 1.5f), 0.02f);
  EXPECT_NEAR(share_at(map, Vec3f(16.5f, 3.0f, 0.0f)), 0.0f, 1e-6f);  // beyond the stand's reach
  EXPECT_EQ(share_at(map, Vec3f(-200.0f, 3.0f, 0.0f)), 0.0f);  // outside the map
  // The share falls off monotonically from the wood into the open.
  float previous = 1.0f;
  for (float x = -10.0f; x <= 10.0f; x += 0.25f) {
    const float s = share_at(map, Vec3f(x, 3.0f, 0.0f));
    EXPECT_LE(s, previous + 1e-6f) << "x " << x;
    previous = s;
  }
}

TEST(CanopyMap, GroundHeightDecidesWhatIsCanopy) {
  // The same surfaces over ground 9 m up: the "canopy" is 1 m above it, below kCanopyHeight, so no cover.
  const CanopyMap map = build_canopy_map(wood_edge(), [](double x, double) { return x < 0.0 ? 9.0 : 0.0; });
  EXPECT_NEAR(share_at(map, Vec3f(-20.0f, 3.0f, 9.0f)), 0.0f, 1e-6f);
}

TEST(CanopyMap, SameForAnyThreadCountAndEmptyWithoutAMap) {
  const ShadowMap overhead = wood_edge();
  CanopyMap one, two;
  tbb::task_arena(1).execute([&] { one = build_canopy_map(overhead, [](double, double) { return 0.0; }); });
  tbb::task_arena(2).execute([&] { two = build_canopy_map(overhead, [](double, double) { return 0.0; }); });
  EXPECT_EQ(one.cover, two.cover);
  EXPECT_EQ(one.depth, two.depth);
  const CanopyMap none = build_canopy_map(ShadowMap{}, [](double, double) { return 0.0; });
  EXPECT_EQ(share_at(none, Vec3f(0.0f, 0.0f, 0.0f)), 0.0f);
}

}  // namespace
}  // namespace silva::render
