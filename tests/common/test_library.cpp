#include "tests/common/test_library.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <utility>

#include "world/world_generator.hpp"

#include <algorithm>

namespace silva::test {

namespace {

using assets::Asset;
using assets::AssetKind;
using Shape = assets::CollisionProxy::Shape;

/// An axis-aligned box mesh from z = 0 to z = h with half width w, one part of the given role.
Mesh box_mesh(float w, float h, Role role, Material material) {
  Mesh m;
  for (int k = 0; k < 8; ++k)
    m.positions.emplace_back((k & 1) ? w : -w, (k & 2) ? w : -w, (k & 4) ? h : 0.0f);
  m.uvs.assign(8, Vec2f::Zero());
  m.indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
               2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  m.compute_normals();
  MeshPart p;
  p.index_count = uint32_t(m.indices.size());
  p.role = role;
  p.material = material;
  m.parts.push_back(p);
  return m;
}

/// An asset with a box mesh and the given proxy.
Asset make(const char* name, AssetKind kind, Role role, Material material, assets::CollisionProxy proxy, float h) {
  Asset a;
  a.name = name;
  a.kind = kind;
  a.role = role;
  a.geometry = std::make_shared<const assets::AssetGeometry>(
      std::vector<Mesh>{box_mesh(std::max(proxy.footprint_radius(), 0.1f), h, role, material)});
  a.proxy = proxy;
  return a;
}

/// Vertical cylinder proxy standing on the ground.
assets::CollisionProxy cylinder(float r, float h) {
  assets::CollisionProxy p;
  p.shape = Shape::Cylinder;
  p.radius = r;
  p.height = h;
  p.center = Vec3f(0, 0, 0.5f * h);
  return p;
}

/// Builds the fixture.
assets::AssetLibrary build() {
  assets::AssetLibrary lib;
  assets::CollisionProxy none;
  assets::CollisionProxy shrub;
  shrub.shape = Shape::Sphere;
  shrub.radius = 0.6f;
  shrub.center = Vec3f(0, 0, 0.5f);
  assets::CollisionProxy rock_box;
  rock_box.shape = Shape::Box;
  rock_box.half_extents = Vec3f(0.5f, 0.4f, 0.3f);
  rock_box.center = Vec3f(0, 0, 0.2f);
  assets::CollisionProxy rock_ball;
  rock_ball.shape = Shape::Sphere;
  rock_ball.radius = 0.4f;
  rock_ball.center = Vec3f(0.1f, 0, 0.2f);
  assets::CollisionProxy log;
  log.shape = Shape::Capsule;
  log.radius = 0.2f;
  log.height = 3.0f;
  log.axis = Vec3f::UnitX();
  log.center = Vec3f(0, 0, 0.2f);
  lib.assets = {
      make("conifer_0", AssetKind::ConiferTree, Role::TreeTrunk, Material::BarkConifer, cylinder(0.25f, 8), 8),
      make("conifer_1", AssetKind::ConiferTree, Role::TreeTrunk, Material::BarkConifer, cylinder(0.35f, 10), 10),
      make("broadleaf_0", AssetKind::BroadleafTree, Role::TreeTrunk, Material::BarkBroadleaf, cylinder(0.3f, 6), 6),
      make("dead_0", AssetKind::DeadTree, Role::DeadTree, Material::BarkDead, cylinder(0.2f, 5), 5),
      make("stump_0", AssetKind::Stump, Role::Stump, Material::Wood, cylinder(0.3f, 0.5f), 0.5f),
      make("shrub_0", AssetKind::Shrub, Role::Shrub, Material::ShrubLeaves, shrub, 1.1f),
      make("rock_0", AssetKind::Rock, Role::Obstacle, Material::Rock, rock_box, 0.5f),
      make("rock_1", AssetKind::Rock, Role::Obstacle, Material::Rock, rock_ball, 0.6f),
      make("log_0", AssetKind::Log, Role::Obstacle, Material::Wood, log, 0.4f),
      make("grass_0", AssetKind::Grass, Role::GroundVegetation, Material::Grass, none, 0.4f),
      make("fern_0", AssetKind::Fern, Role::GroundVegetation, Material::Fern, none, 0.5f),
  };
  lib.index_kinds();
  return lib;
}

}  // namespace

const assets::AssetLibrary& small_library() {
  static const assets::AssetLibrary lib = build();
  return lib;
}

Config small_world_config(int64_t seed, double density) {
  Config cfg;
  cfg.seed = seed;
  cfg.vegetation.density = density;
  cfg.world.extent = 128;
  cfg.world.render_distance = 32;
  cfg.trail.control_points = 12;
  cfg.trail.control_spacing = 10;
  return cfg;
}

world::BuiltWorld build_world(const world::WorldContext& ctx, std::vector<ChunkCoord> coords, int threads) {
  std::sort(coords.begin(), coords.end());
  coords.erase(std::unique(coords.begin(), coords.end()), coords.end());
  std::vector<ChunkContent> chunks(coords.size());
  tbb::task_arena arena(threads);
  arena.execute([&] {
    tbb::parallel_for(size_t(0), coords.size(), [&](size_t k) { chunks[k] = world::generate_chunk(ctx, coords[k]); });
  });
  return world::summarise_world(std::move(chunks));
}

}  // namespace silva::test
