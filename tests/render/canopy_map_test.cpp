#include "render/canopy_map.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "highway_targets.hpp"

#include "render/shadow_pass.hpp"

namespace silva::render {
namespace {

/// Canopy top height of the test scene's wood (m): everything at world x < 0 is covered at this height.
constexpr double kTop = 10.0;

/// A top-down depth map of `region` (flat ground at z = 0, a closed canopy at z = kTop wherever `wooded(x)`),
/// drawn as the renderer would (light looking down) with `resolution` texels along the longer side.
template <class Wooded>
ShadowMap overhead(const AABB& region, int resolution, Wooded wooded) {
  ShadowMap map = shadow_map_frame(Vec3d::UnitZ(), region, resolution);
  const Mat4d to_world = map.world_to_light.inverse();
  map.depth.assign(size_t(map.width) * size_t(map.height), std::numeric_limits<float>::infinity());
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      const Eigen::Vector4d p = to_world * Eigen::Vector4d(map.origin_x + (x + 0.5) * map.texel_size,
                                                           map.origin_y + (y + 0.5) * map.texel_size, 0.0, 1.0);
      const Vec3d top(p.x(), p.y(), wooded(p.x()) ? kTop : 0.0);
      map.depth[size_t(y) * size_t(map.width) + size_t(x)] = float(map.world_to_light.block<1, 3>(2, 0).dot(top));
    }
  return map;
}

/// The box from (-h, -h, -5) to (h, h, 20).
AABB square(float h) {
  AABB region;
  region.extend(Vec3f(-h, -h, -5.0f));
  region.extend(Vec3f(h, h, 20.0f));
  return region;
}

/// 80 x 80 m at 0.125 m texels with a closed canopy over x < 0.
ShadowMap wood_edge() {
  return overhead(square(40.0f), 640, [](double x) { return x < 0.0; });
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

/// The documented share at p, written out plainly: bilinear cover and cover x depth between cell centres,
/// how far p lies below their mean depth, gap = 1 - density x cover x below, share 1 - gap^1.5.
float plain_share(const CanopyMap& map, const Vec3f& p) {
  const Vec3d l = (map.world_to_light * p.cast<double>().homogeneous()).head<3>();
  const double fx = (l.x() - map.origin_x) / map.cell - 0.5, fy = (l.y() - map.origin_y) / map.cell - 0.5;
  if (!(fx > -1.0 && fy > -1.0 && fx < map.width && fy < map.height)) return 0.0f;
  const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
  double cover = 0, cover_depth = 0;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int x = std::clamp(x0 + i, 0, map.width - 1), y = std::clamp(y0 + j, 0, map.height - 1);
      const double w = (i ? fx - x0 : 1.0 - (fx - x0)) * (j ? fy - y0 : 1.0 - (fy - y0));
      const size_t c = size_t(y) * size_t(map.width) + size_t(x);
      cover += w * map.cover[c];
      cover_depth += w * map.cover[c] * map.depth[c];
    }
  if (!(cover > 0.0)) return 0.0f;
  const double below = std::clamp((l.z() - cover_depth / cover) / kCanopySoftness + 0.5, 0.0, 1.0);
  const double gap = 1.0 - kCanopyDensity * cover * below;
  return float(1.0 - std::pow(gap, 1.5));
}

TEST(CanopyMap, RowLookupIsIdenticalOnEveryHighwayTargetAndMatchesThePlainFormula) {
  const CanopyMap map = build_canopy_map(wood_edge(), [](double, double) { return 0.0; });
  std::vector<Vec3f> points;
  for (int i = 0; i < 37; ++i)  // across the edge, at several heights, and a few outside the map
    points.emplace_back(-60.0f + 3.3f * float(i), 0.7f * float(i % 5), float(i % 4) * 4.5f);
  const std::vector<int64_t> targets = test::highway_targets();
  ASSERT_GE(targets.size(), 2u);
  std::vector<float> reference(points.size());
  {
    const test::PinnedTarget portable(targets.back());
    canopy_share_row(map, points.data(), points.size(), reference.data());
  }
  int partial = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    EXPECT_NEAR(reference[i], plain_share(map, points[i]), 2e-4f) << i;
    partial += reference[i] > 0.01f && reference[i] < 0.99f ? 1 : 0;
  }
  EXPECT_GT(partial, 3);
  for (int64_t target : targets) {
    const test::PinnedTarget pinned(target);
    SCOPED_TRACE(hwy::TargetName(target));
    std::vector<float> row(points.size());
    canopy_share_row(map, points.data(), points.size(), row.data());
    for (size_t i = 0; i < points.size(); ++i) {
      EXPECT_EQ(row[i], reference[i]) << i;
      EXPECT_EQ(share_at(map, points[i]), reference[i]) << i;  // one point at a time: the partial-vector path
    }
  }
}

TEST(CanopyMap, RegionGivesThePointsOfTheShadedBoxTheirWholeStand) {
  // Inside a closed wood that runs on past the shaded 40 x 40 m box, a point at the box's corner sees no
  // sky when the map covers canopy_region(box); a map of the box alone blurs "no canopy" in past its edges.
  const AABB box = square(20.0f);
  const AABB grown = canopy_region(box);
  EXPECT_FLOAT_EQ(grown.min.x(), -20.0f - float(kCanopyStandRadius));
  EXPECT_FLOAT_EQ(grown.max.y(), 20.0f + float(kCanopyStandRadius));
  EXPECT_EQ(grown.min.z(), box.min.z());
  EXPECT_EQ(grown.max.z(), box.max.z());
  EXPECT_TRUE(canopy_region(AABB{}).empty());
  const auto flat = [](double, double) { return 0.0; };
  const auto wood = [](double) { return true; };
  const Vec3f corner(19.5f, 19.5f, 0.0f);
  EXPECT_NEAR(share_at(build_canopy_map(overhead(grown, 560, wood), flat), corner), 1.0f, 1e-6f);
  EXPECT_LT(share_at(build_canopy_map(overhead(box, 320, wood), flat), corner), 0.9f);
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
