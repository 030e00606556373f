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
      const auto& control = t.path->control;
      EXPECT_EQ(control.size(), 25u);
      EXPECT_EQ(control.front(), Eigen::Vector2d(0, 0));
      const double limit = 0.5 * extent - kTrailEdgeInset;
      for (const auto& p : control) EXPECT_LE(p.cwiseAbs().maxCoeff(), limit + 1e-9);
      for (const auto& p : t.path->centre) EXPECT_LT(p.cwiseAbs().maxCoeff() + t.path->reach(), 0.5 * extent);
      for (size_t k = 1; k < control.size(); ++k)
        EXPECT_LE((control[k] - control[k - 1]).norm(), c.trail.control_spacing + 1e-9);
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
    EXPECT_EQ(t.path->centre.size(), size_t(24 * kTrailResample + 1));
    EXPECT_EQ(t.nav.points().size(), t.path->centre.size());
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

TEST(Trail, TerrainIsFlatAcrossTheTrailAndSmoothAtItsEdge) {
  Config c = config(11);
  c.terrain.max_elevation = 4;
  const TerrainField f = make_terrain_field(c);
  const Trail t = build_trail(c, f);
  const TrailPath& path = *t.path;
  const double hw = path.half_width;
  for (size_t k = 1; k + 1 < path.centre.size(); k += 37) {
    const Eigen::Vector2d dir = (path.centre[k + 1] - path.centre[k - 1]).normalized();
    const Eigen::Vector2d right(dir.y(), -dir.x()), c0 = path.centre[k];
    auto height = [&](double off) {
      const Eigen::Vector2d p = c0 + off * right;
      return double(terrain_height(f, p.x(), p.y()));
    };
    // Level across (only the worn dip, kTrailWear deep), no step at either edge.
    EXPECT_NEAR(height(-0.9 * hw), height(0.9 * hw), 0.01) << k;
    EXPECT_NEAR(height(0.0), path.bed[k] - kTrailWear, 1e-6) << k;
    for (double side : {-1.0, 1.0}) EXPECT_LT(std::abs(height(side * (hw + 0.01)) - height(side * (hw - 0.01))), 0.01);
    // Beyond the shoulder the terrain is its own again: the mesh there is unaffected by the trail.
    const Eigen::Vector2d far = c0 + (path.reach() + 0.05) * right;
    if (nearest_trail_point(path, far.x(), far.y()).distance >= path.reach()) {
      Config plain = c;
      plain.trail.enabled = false;
      EXPECT_EQ(terrain_height(f, far.x(), far.y()), terrain_height(make_terrain_field(plain), far.x(), far.y()));
    }
  }
}

TEST(Trail, TerrainMeshCarriesTheEdgeCoordinate) {
  Config c = config(21);
  const TerrainField f = make_terrain_field(c);
  const Trail t = build_trail(c, f);
  size_t on_trail = 0, overlays = 0;
  for (ChunkCoord cc : default_world_chunks(c)) {
    const Mesh m = build_terrain_mesh(f, c.terrain.chunk_size, cc);
    ASSERT_EQ(m.parts.size(), 1u);
    EXPECT_EQ(m.parts[0].role, Role::Ground);
    if (!m.parts[0].overlay) continue;
    ++overlays;
    EXPECT_EQ(m.parts[0].overlay->role, Role::Trail);
    EXPECT_EQ(m.parts[0].overlay->material, Material::Trail);
    for (size_t v = 0; v < m.positions.size(); ++v) {
      const Vec3f& p = m.positions[v];
      const TrailPoint q = nearest_trail_point(*t.path, p.x(), p.y());
      EXPECT_FLOAT_EQ(m.uvs[v].x(), float(std::min(q.distance, t.path->reach()) - t.path->half_width));
      on_trail += m.uvs[v].x() < 0.0f;
    }
  }
  EXPECT_GT(overlays, 10u);
  EXPECT_GT(on_trail, 1000u);
}

TEST(Trail, DisabledMeansNoTrail) {
  Config c = config(1);
  c.trail.enabled = false;
  const Trail t = build_trail(c, make_terrain_field(c));
  EXPECT_FALSE(t.enabled);
  for (ChunkCoord cc : {ChunkCoord{0, 0}, ChunkCoord{-1, 0}})
    EXPECT_FALSE(build_terrain_mesh(make_terrain_field(c), 32, cc).parts[0].overlay.has_value());
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
