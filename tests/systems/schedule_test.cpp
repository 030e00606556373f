// The one schedule: its systems, their access declarations, and what a frame leaves behind.
#include "pipeline/schedule/world_schedule.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "components/camera.hpp"
#include "components/chunk.hpp"
#include "components/phase.hpp"
#include "tests/common/test_library.hpp"
#include "world/chunk_cache.hpp"
#include "world/chunk_regions.hpp"
#include "world/chunk_content.hpp"
#include "world/world_generator.hpp"

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
                                             "render_views", "cast_lidar", "write_dataset"}));
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

TEST(Schedule, CamerasWalkingTheTrailStreamTheirChunksWithinTheCacheBound) {
  const world::WorldContext ctx = walk_context();
  const size_t bound = 12;
  WorldSchedule schedule(ctx, bound);
  const auto& nav = ctx.trail.nav;
  for (int k = 0; k <= 30; ++k) {
    const double s = k * nav.length() / 30;
    const Vec3d p = nav.position(s), t = nav.tangent(s);
    world::PlannedFrame f;
    f.camera = Camera::from_fov(96, 64, 90, ctx.config.camera.near, ctx.config.camera.far);
    f.camera.camera_to_world = pose_from_angles(p + Vec3d(0, 0, 1.5), std::atan2(t.y(), t.x()) * 180 / M_PI, 0, 0);
    schedule.ecs().resource<CaptureQueue>().cameras = {schedule.ecs().spawn(f)};
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

}  // namespace
}  // namespace silva::pipeline
