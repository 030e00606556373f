#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "components/camera.hpp"
#include "components/chunk.hpp"
#include "world/chunk_regions.hpp"
#include "systems/stream_plan.hpp"
#include "world/world_summary.hpp"
#include "world/world_generator.hpp"
#include "systems/world_systems.hpp"
#include "tests/common/test_library.hpp"

namespace silva::world {

TEST(StreamPlan, SpawnsPromotesKeepsAndDespawns) {
  const std::vector<ChunkCoord> required = {{0, 0}};
  const std::vector<ChunkCoord> keep = {{0, 0}, {5, 5}};
  // Live: (0,0) as a halo (promote), (1,0) halo (stays: in the ring), (5,5) full (kept by
  // hysteresis), (7,7) full and (9,9) halo (both out of range).
  const std::map<ChunkCoord, bool> live = {
      {{0, 0}, true}, {{1, 0}, true}, {{5, 5}, false}, {{7, 7}, false}, {{9, 9}, true}};
  const StreamPlan plan = plan_stream(required, keep, live, 1);
  EXPECT_TRUE(plan.spawn_full.empty());
  EXPECT_EQ(plan.promote, (std::vector<ChunkCoord>{{0, 0}}));
  EXPECT_EQ(plan.spawn_halo.size(), 7u);  // the ring of 8 minus the live (1,0)
  EXPECT_FALSE(std::count(plan.spawn_halo.begin(), plan.spawn_halo.end(), ChunkCoord{1, 0}));
  EXPECT_EQ(plan.despawn, (std::vector<ChunkCoord>{{7, 7}, {9, 9}}));
  // From nothing: the chunk itself full, its ring as halos.
  const StreamPlan fresh = plan_stream(required, keep, {}, 2);
  EXPECT_EQ(fresh.spawn_full, required);
  EXPECT_EQ(fresh.spawn_halo.size(), 24u);
}

TEST(WorldSystems, OneFrameBuildsEveryPinnedChunkLikeGenerateChunk) {
  const WorldContext ctx = make_world_context(test::small_world_config(31, 10), test::small_library());
  ecs::World w;
  StreamSettings settings = default_stream_settings(ctx);
  settings.pinned = {{0, 0}, {1, 0}, {-1, 2}};
  install_world_systems(w, ctx, settings);
  w.run_frame();
  EXPECT_EQ(full_chunk_count(w), 3u);
  size_t vegetation = 0;
  w.view<const Chunk, const ChunkTerrain, const ChunkObjects>().each(
      [&](const Chunk& c, const ChunkTerrain& t, const ChunkObjects& o) {
        if (c.halo) return;
        ASSERT_TRUE(t.ready && o.resolved && o.populated);
        vegetation += o.objects.size();
        EXPECT_EQ(chunk_hash(assemble_chunk(c.coord, ChunkTerrain(t), ChunkObjects(o))),
                  chunk_hash(generate_chunk(ctx, c.coord)));
      });
  EXPECT_GT(vegetation, 100u);
  EXPECT_EQ(w.view<const VegetationOf>().size_hint(), vegetation);
  // A second frame with nothing changed changes nothing.
  const size_t entities = w.entity_count();
  w.run_frame();
  EXPECT_EQ(w.entity_count(), entities);
}

TEST(WorldSystems, WalkingTheTrailKeepsChunksBoundedAndLeavesNoOrphans) {
  Config cfg = test::small_world_config(9, 5);
  cfg.world.extent = 512;  // room for a trail long enough to stream many chunks in and out
  cfg.trail.control_points = 30;
  cfg.trail.control_spacing = 12;
  cfg.vegetation.ground = false;  // keep the test fast: streaming does not depend on ground cover
  cfg.camera.far = 30;            // the view stays inside the render distance (32 m)
  const WorldContext ctx = make_world_context(cfg, test::small_library());
  const double s = ctx.chunk_size();
  ecs::World w;
  const StreamSettings settings = default_stream_settings(ctx);
  install_world_systems(w, ctx, settings);
  const ecs::Entity camera = w.spawn(WorldCamera{Camera::from_fov(320, 240, 90, cfg.camera.near, cfg.camera.far)});
  // Full chunks lie within render distance + max(hysteresis, halo reach) of the camera.
  const double reach =
      settings.render_distance + std::max(settings.hysteresis, ctx.neighbour_ring * s * std::sqrt(2.0));
  const size_t bound = chunks_in_disc(0, 0, reach, s).size();
  const auto& nav = ctx.trail.nav;
  std::set<ChunkCoord> ever;
  size_t peak = 0;
  for (int k = 0; k <= 60; ++k) {
    const double at = k * nav.length() / 60;
    const Vec3d p = nav.position(at), t = nav.tangent(at);
    w.get<WorldCamera>(camera).camera.camera_to_world =
        pose_from_angles(p + Vec3d(0, 0, 1.5), std::atan2(t.y(), t.x()) * 180 / M_PI, 0, 0);
    w.run_frame();
    const size_t full = full_chunk_count(w);
    peak = std::max(peak, full);
    ASSERT_LE(full, bound) << "step " << k;
    // Every chunk within the render distance is live and resolved.
    std::set<ChunkCoord> resolved;
    size_t owned = 0;
    w.view<const Chunk, const ChunkObjects>().each([&](const Chunk& c, const ChunkObjects& o) {
      if (!c.halo) {
        ASSERT_TRUE(o.resolved && o.populated);
        resolved.insert(c.coord);
        ever.insert(c.coord);
        owned += o.objects.size();
      }
    });
    for (ChunkCoord c : chunks_in_disc(p.x(), p.y(), settings.render_distance, s)) ASSERT_TRUE(resolved.count(c));
    // No vegetation entity outlives its chunk, and each chunk's objects are entities exactly once.
    size_t vegetation = 0;
    w.view<const VegetationOf>().each([&](const VegetationOf& v) {
      ++vegetation;
      ASSERT_TRUE(w.alive(v.chunk));
      ASSERT_TRUE(w.has<Chunk>(v.chunk));
    });
    EXPECT_EQ(vegetation, owned) << "step " << k;
  }
  EXPECT_GT(ever.size(), bound);  // the walk really streamed chunks in and out
  EXPECT_GT(peak, 0u);
}

}  // namespace silva::world
