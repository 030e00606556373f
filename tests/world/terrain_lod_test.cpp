#include "world/terrain_lod.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <utility>

#include "render/renderer.hpp"
#include "world/terrain.hpp"
#include "world/trail_path.hpp"

namespace silva::world {

namespace {

/// Terrain field of the default config with `seed`, relief raised to 3 m so that simplification
/// has real work to do.
TerrainField field(int64_t seed) {
  Config c;
  c.seed = seed;
  c.terrain.max_elevation = 3.0;
  return make_terrain_field(c);
}

/// An edge as its two end positions, in a fixed order.
using Edge = std::pair<std::array<float, 3>, std::array<float, 3>>;

/// Edges used by exactly one triangle of `m` (its open border), by position.
std::set<Edge> border_edges(const Mesh& m) {
  std::multiset<Edge> all;
  for (size_t t = 0; t < m.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const Vec3f& a = m.positions[m.indices[t + size_t(k)]];
      const Vec3f& b = m.positions[m.indices[t + size_t((k + 1) % 3)]];
      std::array<float, 3> pa{a.x(), a.y(), a.z()}, pb{b.x(), b.y(), b.z()};
      all.insert(pa < pb ? Edge{pa, pb} : Edge{pb, pa});
    }
  std::set<Edge> once;
  for (const Edge& e : all)
    if (all.count(e) == 1) once.insert(e);
  return once;
}

/// Height of `m`'s surface above (x, y) from the triangle containing it; NaN if none does.
double surface_at(const Mesh& m, double x, double y) {
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    const Vec3f& a = m.positions[m.indices[t]];
    const Vec3f& b = m.positions[m.indices[t + 1]];
    const Vec3f& c = m.positions[m.indices[t + 2]];
    const double det = double(b.x() - a.x()) * (c.y() - a.y()) - double(c.x() - a.x()) * (b.y() - a.y());
    if (det == 0.0) continue;
    const double u = ((x - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (y - a.y())) / det;
    const double v = (double(b.x() - a.x()) * (y - a.y()) - (x - a.x()) * double(b.y() - a.y())) / det;
    if (u < -1e-6 || v < -1e-6 || u + v > 1.0 + 1e-6) continue;
    return a.z() + u * (b.z() - a.z()) + v * (c.z() - a.z());
  }
  return std::nan("");
}

}  // namespace

TEST(TerrainLod, LevelShrinksAndKeepsTheGroundPart) {
  const Mesh full = build_terrain_mesh(field(3), 32, ChunkCoord{2, -1});
  const Mesh level = build_terrain_lod(full);
  // A real reduction even on 3 m relief, not a token one.
  EXPECT_LT(level.triangle_count(), full.triangle_count() / 2);
  EXPECT_GT(level.triangle_count(), 0u);
  ASSERT_EQ(level.parts.size(), 1u);
  EXPECT_EQ(level.parts[0].role, Role::Ground);
  EXPECT_EQ(level.parts[0].index_count, level.indices.size());
  EXPECT_EQ(level.normals.size(), level.positions.size());
  EXPECT_EQ(level.uvs.size(), level.positions.size());
  // Only a one-part mesh is a terrain mesh.
  Mesh two_parts = full;
  two_parts.parts.push_back(two_parts.parts[0]);
  EXPECT_EQ(build_terrain_lod(two_parts).triangle_count(), 0u);
}

TEST(TerrainLod, KeepsTheTrailBandAtFullDetail) {
  // A chunk the trail crosses, 80 m from its start.
  const TerrainField f = field(5);
  const Eigen::Vector2d at = f.trail->centre[200];
  const Mesh full = build_terrain_mesh(f, 32, ChunkCoord{int32_t(std::floor(at.x() / 32)), int32_t(std::floor(at.y() / 32))});
  ASSERT_TRUE(full.parts[0].overlay.has_value());
  const Mesh level = build_terrain_lod(full);
  ASSERT_GT(level.triangle_count(), 0u);
  using Corner = std::array<float, 5>;  // position and uv
  auto corner = [](const Mesh& m, uint32_t v) {
    return Corner{m.positions[v].x(), m.positions[v].y(), m.positions[v].z(), m.uvs[v].x(), m.uvs[v].y()};
  };
  std::set<std::array<Corner, 3>> kept;
  for (size_t k = 0; k < level.indices.size(); k += 3)
    kept.insert({corner(level, level.indices[k]), corner(level, level.indices[k + 1]), corner(level, level.indices[k + 2])});
  size_t band = 0;
  for (size_t k = 0; k < full.indices.size(); k += 3) {
    const uint32_t* t = &full.indices[k];
    if (std::min({full.uvs[t[0]].x(), full.uvs[t[1]].x(), full.uvs[t[2]].x()}) >= float(kTrailShoulder)) continue;
    ++band;
    EXPECT_TRUE(kept.count({corner(full, t[0]), corner(full, t[1]), corner(full, t[2])})) << k;
  }
  EXPECT_GT(band, 100u);
}

TEST(TerrainLod, BorderIsTheFullMeshBorder) {
  const Mesh full = build_terrain_mesh(field(11), 32, ChunkCoord{-3, 4});
  const std::set<Edge> border = border_edges(full);
  ASSERT_EQ(border.size(), size_t(4 * 64));
  EXPECT_TRUE(border_edges(build_terrain_lod(full)) == border);
}

TEST(TerrainLod, SurfaceStaysWithinTwoCentimetres) {
  const Mesh full = build_terrain_mesh(field(29), 32, ChunkCoord{0, 1});
  const Mesh level = build_terrain_lod(full);
  double worst = 0;
  for (const Vec3f& p : full.positions) {
    const double h = surface_at(level, p.x(), p.y());
    ASSERT_FALSE(std::isnan(h)) << "the level leaves a hole at " << p.transpose();
    worst = std::max(worst, std::abs(h - double(p.z())));
  }
  EXPECT_GT(worst, 0.0);  // the level did move the surface somewhere
  EXPECT_LT(worst, 0.02);
}

TEST(TerrainLod, NeighboursAtDifferentLevelsLeaveNoCrack) {
  // A grazing view across the border x = 32 m between chunk (0, 0) and chunk (1, 0): any gap
  // between them would show the background.
  const TerrainField f = field(7);
  const Mesh west = build_terrain_mesh(f, 32, ChunkCoord{0, 0});
  const Mesh east = build_terrain_mesh(f, 32, ChunkCoord{1, 0});
  const Mesh west_lod = build_terrain_lod(west), east_lod = build_terrain_lod(east);
  const std::pair<const Mesh*, const Mesh*> pairs[] = {{&west, &east_lod}, {&west_lod, &east}, {&west_lod, &east_lod}};
  Camera cam = Camera::from_fov(320, 180, 40, 0.05, 200);
  cam.camera_to_world = pose_from_angles(Vec3d(24, 16, terrain_height(f, 24, 16) + 3.0), 0, -25, 0);
  for (const auto& [a, b] : pairs) {
    render::Scene scene;
    for (const Mesh* m : {a, b}) {
      scene.meshes.emplace_back().lods = {m};
      render::Instance inst;
      inst.mesh = uint32_t(scene.meshes.size() - 1);
      scene.instances.push_back(inst);
    }
    render::Renderer renderer;
    const render::VisibilityBuffer& vis = renderer.render_visibility(scene, cam, render::RenderOptions{});
    size_t empty = 0, seen[2] = {0, 0};
    for (uint32_t id : vis.instance) {
      if (id == render::kNoInstance) ++empty;
      else ++seen[id];
    }
    EXPECT_EQ(empty, 0u);
    EXPECT_GT(seen[0], 1000u);  // both chunks are in view
    EXPECT_GT(seen[1], 1000u);
  }
}

}  // namespace silva::world
