// The one schedule: its systems, their access declarations, and what a frame leaves behind.
#include "pipeline/schedule/world_schedule.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "components/camera.hpp"
#include "components/chunk.hpp"
#include "components/phase.hpp"
#include "systems/aim_camera.hpp"
#include "systems/prefetch_chunks.hpp"
#include "tests/common/test_library.hpp"
#include "world/chunk_cache.hpp"
#include "world/chunk_regions.hpp"
#include "world/chunk_content.hpp"
#include "world/world_generator.hpp"
#include "world/world_summary.hpp"

namespace silva::pipeline {
namespace {

/// A small world context whose trail the tests walk.
world::WorldContext walk_context() {
  Config cfg = test::small_world_config(9, 1);
  cfg.vegetation.ground = false;  // streaming does not depend on content: keep it quick
  cfg.camera.far = 60;
  return world::make_world_context(cfg, test::small_library());
}

TEST(Schedule, RegistersEverySystemInPhaseOrderWithoutConflicts) {
  const world::WorldContext ctx = walk_context();
  WorldSchedule schedule(ctx, 16);
  std::vector<std::string> names;
  int last_phase = -1;
  for (const ecs::SystemStats& s : schedule.ecs().system_stats()) {
    names.push_back(s.name);
    EXPECT_GE(s.phase, last_phase) << s.name;
    last_phase = s.phase;
  }
  EXPECT_EQ(names, (std::vector<std::string>{"plan_captures", "aim_camera", "stream_chunks", "generate_terrain",
                                             "place_vegetation", "resolve_overlaps", "store_chunks", "prepare_scene",
                                             "prefetch_chunks", "render_views", "cast_lidar", "write_dataset"}));
  EXPECT_TRUE(schedule.ecs().schedule_conflicts().empty());
}

TEST(Schedule, BuildEqualsTheLibraryAndLeavesNoChunkEntities) {
  const world::WorldContext ctx = world::make_world_context(test::small_world_config(21, 5), test::small_library());
  const std::vector<ChunkCoord> coords = world::chunks_in_disc(-8, 12, 45, 32);
  WorldSchedule schedule(ctx, coords.size());
  const world::BuiltWorld built = schedule.build(coords);
  const world::BuiltWorld reference = test::build_world(ctx, coords, 1);
  ASSERT_EQ(built.chunks.size(), coords.size());
  EXPECT_EQ(built.hash, reference.hash);
  EXPECT_GT(built.totals.objects, 100u);
  EXPECT_EQ(schedule.ecs().view<const Chunk>().size_hint(), 0u);  // work entities despawned
  for (const ChunkContent& c : built.chunks) EXPECT_TRUE(c.terrain_lod.positions.empty());  // not for drawing
  EXPECT_EQ(schedule.ecs().resource<world::ChunkCache>().size(), 0u);  // moved out of the cache
}

TEST(Schedule, ChunksBuiltForDrawingCarryTheirCoarseTerrain) {
  const world::WorldContext ctx = walk_context();
  WorldSchedule schedule(ctx, 8);
  EXPECT_EQ(schedule.warm({{1, 0}, {0, 0}, {1, 0}}).chunks, 2u);
  const world::ChunkCache& cache = schedule.ecs().resource<world::ChunkCache>();
  for (ChunkCoord coord : {ChunkCoord{0, 0}, ChunkCoord{1, 0}}) {
    ASSERT_NE(cache.find(coord), nullptr);
    const ChunkContent& c = *cache.find(coord);
    ChunkContent fresh = world::generate_chunk(ctx, c.coord);
    world::add_terrain_level(fresh);
    EXPECT_EQ(c.terrain_lod.positions, fresh.terrain_lod.positions);
    EXPECT_FALSE(c.terrain_lod.positions.empty());
  }
}

/// Frame `k` of `steps` along the trail: a small camera looking along it.
world::PlannedFrame trail_frame(const world::WorldContext& ctx, int k, int steps) {
  const auto& nav = ctx.trail.nav;
  const double s = k * nav.length() / steps;
  const Vec3d p = nav.position(s), t = nav.tangent(s);
  world::PlannedFrame f;
  f.camera = Camera::from_fov(96, 64, 90, ctx.config.camera.near, ctx.config.camera.far);
  f.camera.camera_to_world = pose_from_angles(p + Vec3d(0, 0, 1.5), std::atan2(t.y(), t.x()) * 180 / M_PI, 0, 0);
  return f;
}

TEST(Schedule, CamerasWalkingTheTrailStreamTheirChunksWithinTheCacheBound) {
  const world::WorldContext ctx = walk_context();
  const size_t bound = 12;
  WorldSchedule schedule(ctx, bound);
  for (int k = 0; k <= 30; ++k) {
    schedule.ecs().resource<CaptureQueue>().cameras = {schedule.ecs().spawn(trail_frame(ctx, k, 30))};
    schedule.ecs().resource<CaptureQueue>().next = 0;
    schedule.ecs().run_phases(Phase::Stream, Phase::Prepare);
    const world::ChunkCache& cache = schedule.ecs().resource<world::ChunkCache>();
    const auto& view = schedule.ecs().resource<ViewChunks>().coords;
    ASSERT_FALSE(view.empty());
    for (ChunkCoord c : view) ASSERT_NE(cache.find(c), nullptr) << "step " << k;
    ASSERT_LE(cache.size(), std::max(bound, view.size())) << "step " << k;
    EXPECT_EQ(schedule.ecs().view<const Chunk>().size_hint(), 0u);
  }
  EXPECT_GT(schedule.ecs().resource<world::ChunkCache>().generated(), bound);  // chunks streamed in and out
}

TEST(Schedule, TheNextFramesChunksMadeWhileAFrameRendersLeaveTheCacheAsStreamingThemWould) {
  const world::WorldContext ctx = walk_context();
  const size_t bound = 12;
  const int steps = 24;
  WorldSchedule queued(ctx, bound), alone(ctx, bound);  // all cameras queued (prefetching), or one at a time
  CaptureQueue& queue = queued.ecs().resource<CaptureQueue>();
  for (int k = 0; k <= steps; ++k) queue.cameras.push_back(queued.ecs().spawn(trail_frame(ctx, k, steps)));
  size_t prefetched = 0;
  for (int k = 0; k <= steps; ++k) {
    queued.ecs().run_phases(Phase::Stream, Phase::Prepare);
    const std::vector<ChunkCoord> started = queued.ecs().resource<systems::PrefetchedChunks>().started();
    if (k < steps) {  // what the next frame's view lacks, made while this frame renders
      const Camera& next = trail_frame(ctx, k + 1, steps).camera;
      EXPECT_EQ(started, queued.ecs().resource<world::ChunkCache>().missing(
                             systems::capture_chunks(next, ctx.chunk_size(), 0.0))) << "step " << k;
    } else {
      EXPECT_TRUE(started.empty());  // no camera follows the last
    }
    prefetched += started.size();
    alone.ecs().resource<CaptureQueue>().cameras = {alone.ecs().spawn(trail_frame(ctx, k, steps))};
    alone.ecs().resource<CaptureQueue>().next = 0;
    alone.ecs().run_phases(Phase::Stream, Phase::Prepare);
    const world::ChunkCache& a = queued.ecs().resource<world::ChunkCache>();
    const world::ChunkCache& b = alone.ecs().resource<world::ChunkCache>();
    ASSERT_EQ(a.recency(), b.recency()) << "step " << k;
    ASSERT_EQ(a.generated(), b.generated()) << "step " << k;
    for (ChunkCoord c : a.recency()) ASSERT_EQ(world::chunk_hash(*a.find(c)), world::chunk_hash(*b.find(c)));
  }
  EXPECT_GT(prefetched, 10u);
}

TEST(Schedule, PrefetchedChunksAreHandedOverOnlyWhenTheyAreExactlyTheOnesWanted) {
  const world::WorldContext ctx = walk_context();
  systems::PrefetchedChunks prefetched;
  EXPECT_TRUE(prefetched.take({{0, 0}}).empty());  // nothing started
  prefetched.start(ctx, {{0, 0}, {1, 0}});
  EXPECT_TRUE(prefetched.take({{0, 0}}).empty());  // another set: dropped
  EXPECT_TRUE(prefetched.started().empty());
  prefetched.start(ctx, {{0, 0}, {1, 0}});
  const auto got = prefetched.take({{0, 0}, {1, 0}});
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(world::chunk_hash(*got[1]), world::chunk_hash(world::drawable_chunk(ctx, {1, 0})));
  EXPECT_EQ(got[1]->terrain_lod.positions, world::drawable_chunk(ctx, {1, 0}).terrain_lod.positions);
}

TEST(Schedule, ChunksAskedBetweenFramesAreStreamedByTheSystemsInTheOrderAsked) {
  const world::WorldContext ctx = walk_context();
  WorldSchedule schedule(ctx, 64);
  ScheduleChunks source(schedule);
  const std::vector<ChunkCoord> asked{{2, 1}, {0, 0}, {1, 0}};
  const auto got = source.require(ctx, asked);
  ASSERT_EQ(got.size(), asked.size());
  for (size_t k = 0; k < asked.size(); ++k) {
    EXPECT_EQ(got[k]->coord, asked[k]);
    const ChunkContent alone = world::drawable_chunk(ctx, asked[k]);
    EXPECT_EQ(world::chunk_hash(*got[k]), world::chunk_hash(alone));
    EXPECT_EQ(got[k]->terrain_lod.indices, alone.terrain_lod.indices);  // drawable: with the coarse terrain
  }
  const world::ChunkCache& cache = schedule.ecs().resource<world::ChunkCache>();
  EXPECT_EQ(cache.generated(), 3u);
  EXPECT_EQ(cache.recency().front(), (ChunkCoord{1, 0}));  // the last asked is the most recent
  // Asking again streams only the chunk the cache lacks, and leaves no chunk entity behind.
  schedule.chunks({{0, 0}, {3, 3}});
  EXPECT_EQ(cache.generated(), 4u);
  EXPECT_EQ(schedule.ecs().view<const Chunk>().size_hint(), 0u);
}

}  // namespace
}  // namespace silva::pipeline
