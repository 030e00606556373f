#include "world/trail.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/error.hpp"
#include "world/chunk_regions.hpp"

namespace silva::world {

namespace {
Config config(int64_t seed) {
  Config c;
  c.seed = seed;
  return c;
}
}  // namespace

TEST(Trail, StaysInsideTheCaptureRegionAndStartsAtOrigin) {
  for (int64_t seed : {int64_t{1}, int64_t{2}, int64_t{3}, int64_t{42}, int64_t{9999999999}}) {
    for (double extent : {512.0, 100.0}) {
      Config c = config(seed);
      c.world.extent = extent;
      const TerrainField f = make_terrain_field(c);
      const Trail t = build_trail(c, f);
      ASSERT_TRUE(t.enabled);
      EXPECT_EQ(t.control.size(), 25u);
      EXPECT_EQ(t.control.front(), Eigen::Vector2d(0, 0));
      const double limit = 0.5 * extent - kTrailEdgeInset;
      for (const auto& p : t.control) EXPECT_LE(p.cwiseAbs().maxCoeff(), limit + 1e-9);
      for (const Vec3f& v : t.lateral) EXPECT_LT(v.head<2>().cwiseAbs().maxCoeff(), 0.5 * extent);
      for (size_t k = 1; k < t.control.size(); ++k)
        EXPECT_LE((t.control[k] - t.control[k - 1]).norm(), c.trail.control_spacing + 1e-9);
    }
  }
}

TEST(Trail, LongEnoughForTheAutopilot) {
  for (int64_t seed : {1, 7, 123, 5555}) {
    Config c = config(seed);
    const Trail t = build_trail(c, make_terrain_field(c));
    // 24 steps of 20 m; reflections may fold it, but it stays several hundred metres long,
    // so 230 autopilot points are ~2 m apart.
    EXPECT_GT(t.nav.length(), 300.0) << seed;
    EXPECT_EQ(t.centre.size(), size_t(24 * kTrailResample + 1));
    EXPECT_EQ(t.nav.points().size(), t.centre.size());
    const int n = c.captures.autopilot_points;
    for (int i = 0; i + 1 < n; ++i) {
      const double s0 = i * t.nav.length() / (n - 1), s1 = (i + 1) * t.nav.length() / (n - 1);
      EXPECT_GT((t.nav.position(s1) - t.nav.position(s0)).norm(), 0.5);
    }
  }
}

TEST(Trail, NavSplineFollowsTheTerrain) {
  Config c = config(3);
  c.terrain.max_elevation = 5;
  const TerrainField f = make_terrain_field(c);
  const Trail t = build_trail(c, f);
  for (const Vec3d& p : t.nav.points()) EXPECT_EQ(float(p.z()), surface_height(f, p.x(), p.y()));
  for (int k = 0; k <= 100; ++k) EXPECT_NEAR(t.nav.tangent(k * t.nav.length() / 100).norm(), 1.0, 1e-9);
}

TEST(Trail, LateralSamplesAreSymmetricAndOdd) {
  static_assert(kTrailLateralSamples % 2 == 1);
  Config c = config(11);
  const TerrainField f = make_terrain_field(c);
  const Trail t = build_trail(c, f);
  for (size_t k = 0; k < t.centre.size(); k += 97) {
    const Vec3f* row = &t.lateral[k * kTrailLateralSamples];
    const Eigen::Vector2d mid = row[kTrailLateralSamples / 2].head<2>().cast<double>();
    EXPECT_LT((mid - t.centre[k]).norm(), 1e-3);
    const double across = (row[0].head<2>() - row[kTrailLateralSamples - 1].head<2>()).norm();
    EXPECT_NEAR(across, c.trail.width, 1e-3);
    for (int q = 0; q < kTrailLateralSamples; ++q)
      EXPECT_NEAR(row[q].z(), surface_height(f, row[q].x(), row[q].y()) + kTrailLift, 1e-5);
  }
}

TEST(Trail, MeshPiecesCoverTheTrailOnce) {
  Config c = config(21);
  const TerrainField f = make_terrain_field(c);
  const Trail t = build_trail(c, f);
  size_t triangles = 0;
  for (ChunkCoord cc : default_world_chunks(c)) {
    const Mesh m = build_trail_mesh(t, c.terrain.chunk_size, cc);
    if (m.indices.empty()) continue;
    triangles += m.triangle_count();
    ASSERT_EQ(m.parts.size(), 1u);
    EXPECT_EQ(m.parts[0].role, Role::Trail);
    EXPECT_EQ(m.parts[0].material, Material::Trail);
    for (const Vec2f& uv : m.uvs) {
      EXPECT_GE(uv.x(), 0.0f);
      EXPECT_LE(uv.x(), 1.0f);
      EXPECT_GE(uv.y(), 0.0f);
      EXPECT_LE(uv.y(), float(t.nav.length()) + 1e-3f);
    }
  }
  EXPECT_EQ(triangles, (t.centre.size() - 1) * (kTrailLateralSamples - 1) * 2);
}

TEST(Trail, DisabledMeansNoTrail) {
  Config c = config(1);
  c.trail.enabled = false;
  const Trail t = build_trail(c, make_terrain_field(c));
  EXPECT_FALSE(t.enabled);
  EXPECT_TRUE(build_trail_mesh(t, 32, ChunkCoord{0, 0}).indices.empty());
  EXPECT_TRUE(trail_segments_near(t, -10, -10, 10, 10, 5).empty());
}

TEST(Trail, TooSmallRegionIsBadInput) {
  Config c = config(1);
  c.world.extent = 60;
  EXPECT_THROW(build_trail(c, make_terrain_field(c)), InputError);
}

TEST(Trail, DifferentSeedsDifferentTrails) {
  Config a = config(1), b = config(2);
  EXPECT_NE(trail_control_points(a)[5], trail_control_points(b)[5]);
  EXPECT_EQ(trail_control_points(a), trail_control_points(a));
}

}  // namespace silva::world
