#include "world/terrain.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace silva::world {

namespace {
Config config(int64_t seed) {
  Config c;
  c.seed = seed;
  return c;
}
}  // namespace

TEST(Terrain, ChunkSeamsAreBitExact) {
  const TerrainField f = make_terrain_field(config(17));
  const int n = 64;  // 32 m / 0.5 m
  const Mesh a = build_terrain_mesh(f, 32, ChunkCoord{-1, 2});
  const Mesh right = build_terrain_mesh(f, 32, ChunkCoord{0, 2});
  const Mesh up = build_terrain_mesh(f, 32, ChunkCoord{-1, 3});
  ASSERT_EQ(a.positions.size(), size_t((n + 1) * (n + 1)));
  for (int k = 0; k <= n; ++k) {
    const size_t east = size_t(k * (n + 1) + n), west = size_t(k * (n + 1));
    EXPECT_EQ(a.positions[east], right.positions[west]);
    EXPECT_EQ(a.normals[east], right.normals[west]);
    EXPECT_EQ(a.uvs[east], right.uvs[west]);
    const size_t north = size_t(n * (n + 1) + k), south = size_t(k);
    EXPECT_EQ(a.positions[north], up.positions[south]);
    EXPECT_EQ(a.normals[north], up.normals[south]);
  }
}

TEST(Terrain, MeshFollowsTheHeightFunction) {
  Config c = config(5);
  c.terrain.max_elevation = 3.0;
  const TerrainField f = make_terrain_field(c);
  const Mesh m = build_terrain_mesh(f, 32, ChunkCoord{3, -4});
  ASSERT_EQ(m.parts.size(), 1u);
  EXPECT_EQ(m.parts[0].role, Role::Ground);
  EXPECT_EQ(m.parts[0].material, Material::Ground);
  EXPECT_EQ(m.triangle_count(), size_t(64 * 64 * 2));
  float lo = 1e9f, hi = -1e9f;
  for (size_t v = 0; v < m.positions.size(); ++v) {
    const Vec3f p = m.positions[v];
    EXPECT_EQ(p.z(), terrain_height(f, p.x(), p.y()));
    EXPECT_EQ(p.z(), surface_height(f, p.x(), p.y()));
    EXPECT_LE(std::abs(p.z()), 3.0f);
    EXPECT_NEAR(m.normals[v].norm(), 1.0f, 1e-5f);
    EXPECT_GT(m.normals[v].z(), 0.0f);
    lo = std::min(lo, p.z());
    hi = std::max(hi, p.z());
  }
  EXPECT_GT(hi - lo, 0.05f);  // not flat
  // Positions span exactly the chunk; uv.x is the distance to the trail's edge, at most the shoulder.
  EXPECT_EQ(m.positions.front(), Vec3f(96, -128, m.positions.front().z()));
  EXPECT_EQ(m.positions.back().head<2>(), Vec2f(128, -96));
  for (const Vec2f& uv : m.uvs) EXPECT_LE(uv.x(), float(kTrailShoulder));
}

TEST(Terrain, TrianglesFaceUp) {
  const TerrainField f = make_terrain_field(config(2));
  const Mesh m = build_terrain_mesh(f, 8, ChunkCoord{0, 0});
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    const Vec3f a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                c = m.positions[m.indices[3 * t + 2]];
    EXPECT_GT((b - a).cross(c - a).z(), 0.0f);
  }
}

TEST(Terrain, SurfaceHeightInterpolatesTheMeshTriangles) {
  const TerrainField f = make_terrain_field(config(9));
  // Inside cell (0,0): lower-right triangle (fx >= fy) uses h00, h10, h11.
  const double h00 = terrain_height(f, 0, 0), h10 = terrain_height(f, 0.5, 0), h11 = terrain_height(f, 0.5, 0.5);
  const double fx = 0.6, fy = 0.2;
  EXPECT_NEAR(surface_height(f, fx * 0.5, fy * 0.5), h00 + fx * (h10 - h00) + fy * (h11 - h10), 1e-6);
}

TEST(Terrain, SeedAndElevationChangeTheField) {
  const TerrainField a = make_terrain_field(config(1)), b = make_terrain_field(config(2));
  Config flat = config(1);
  flat.terrain.max_elevation = 0;
  flat.trail.enabled = false;  // the trail's worn bed would dip below 0
  const TerrainField z = make_terrain_field(flat);
  int differ = 0;
  for (int k = 0; k < 100; ++k) {
    differ += terrain_height(a, k * 3.3, k * 1.1) != terrain_height(b, k * 3.3, k * 1.1);
    EXPECT_EQ(terrain_height(z, k * 3.3, k * 1.1), 0.0f);
  }
  EXPECT_GT(differ, 95);
}

}  // namespace silva::world
