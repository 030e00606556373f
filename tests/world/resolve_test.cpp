#include "world/resolve.hpp"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/narrowphase/collision.h>
#include <gtest/gtest.h>

#include <memory>

#include "world/collision_proxy.hpp"
#include "tests/common/test_library.hpp"

namespace silva::world {

namespace {

/// Number of colliding pairs among the solid proxies of a world, found by FCL's own broad phase.
size_t fcl_collisions(const WorldContext& ctx, const BuiltWorld& w) {
  std::vector<std::unique_ptr<fcl::CollisionObjectf>> objects;
  for (const ChunkContent& c : w.chunks)
    for (const Vegetation& v : c.objects) {
      const PlacedProxy p = place_proxy(ctx.library->assets[v.asset].proxy, v.position, v.yaw, v.scale);
      if (p.geometry) objects.push_back(std::make_unique<fcl::CollisionObjectf>(p.geometry, p.transform));
    }
  fcl::DynamicAABBTreeCollisionManagerf manager;
  std::vector<fcl::CollisionObjectf*> raw;
  for (auto& o : objects) raw.push_back(o.get());
  manager.registerObjects(raw);
  manager.setup();
  struct Data {
    size_t hits = 0;
  } data;
  manager.collide(&data, [](fcl::CollisionObjectf* a, fcl::CollisionObjectf* b, void* d) {
    fcl::CollisionRequestf req;
    fcl::CollisionResultf res;
    if (fcl::collide(a, b, req, res) > 0) ++static_cast<Data*>(d)->hits;
    return false;
  });
  return data.hits;
}

}  // namespace

TEST(Resolve, NoSolidProxiesCollideAfterResolve) {
  for (double density : {1.0, 5.0, 25.0}) {
    for (int64_t seed : {1, 2, 3}) {
      const WorldContext ctx = make_world_context(test::small_world_config(seed, density), test::small_library());
      const BuiltWorld w = test::build_world(ctx, {{-1, -1}, {-1, 0}, {0, -1}, {0, 0}, {1, 0}, {0, 1}}, 2);
      EXPECT_EQ(fcl_collisions(ctx, w), 0u) << "seed " << seed << " density " << density;
      if (density == 25.0) {
        EXPECT_GT(w.totals.adjusted, 0u);
        EXPECT_GT(w.totals.narrow_queries, 0u);
      }
    }
  }
}

TEST(Resolve, MovedObjectsStayWellInsideTheirChunk) {
  const WorldContext ctx = make_world_context(test::small_world_config(5, 25), test::small_library());
  const BuiltWorld w = test::build_world(ctx, {{0, 0}, {1, 0}, {0, 1}, {1, 1}}, 2);
  size_t moved = 0;
  for (const ChunkContent& c : w.chunks)
    for (const Vegetation& v : c.objects) {
      const double x0 = c.coord.i * 32.0, y0 = c.coord.j * 32.0;
      EXPECT_GE(v.position.x(), x0);
      EXPECT_LT(v.position.x(), x0 + 32);
      EXPECT_GE(v.position.y(), y0);
      EXPECT_LT(v.position.y(), y0 + 32);
      if (v.placement != Placement::Adjusted) continue;
      ++moved;
      const double margin = 2 * ctx.max_footprint;
      EXPECT_GE(v.position.x(), x0 + margin);
      EXPECT_LE(v.position.x(), x0 + 32 - margin);
    }
  EXPECT_GT(moved, 0u);
}

TEST(Resolve, GroundVegetationAvoidsSolids) {
  const WorldContext ctx = make_world_context(test::small_world_config(6, 20), test::small_library());
  const BuiltWorld w = test::build_world(ctx, {{0, 0}, {1, 0}}, 1);
  std::vector<const Vegetation*> solids, ground;
  for (const ChunkContent& c : w.chunks)
    for (const Vegetation& v : c.objects) (v.role == Role::GroundVegetation ? ground : solids).push_back(&v);
  ASSERT_FALSE(solids.empty());
  ASSERT_FALSE(ground.empty());
  for (const Vegetation* g : ground)
    for (const Vegetation* s : solids) {
      const float reach = ctx.footprint[g->asset] * g->scale + ctx.footprint[s->asset] * s->scale;
      EXPECT_GE((g->position - s->position).head<2>().norm(), reach - 1e-4f);
    }
  EXPECT_GT(w.totals.ground_dropped, 0u);
}

TEST(Resolve, InstanceIdsArePackedAndUnique) {
  const WorldContext ctx = make_world_context(test::small_world_config(7, 10), test::small_library());
  const BuiltWorld w = test::build_world(ctx, {{-3, 2}}, 1);
  uint32_t next = 1;
  for (const Vegetation& v : w.chunks[0].objects) {
    if (!role_has_instances(v.role)) {
      EXPECT_EQ(v.instance_id, 0u);
      continue;
    }
    EXPECT_EQ(v.instance_id, (uint32_t(uint8_t(-3)) << 24) | (2u << 16) | next);
    ++next;
  }
  EXPECT_GT(next, 2u);
}

}  // namespace silva::world
