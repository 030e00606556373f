#include "pipeline/schedule/world_schedule.hpp"

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>

#include "components/camera.hpp"
#include "components/chunk.hpp"
#include "components/phase.hpp"
#include "components/world_source.hpp"
#include "core/stopwatch.hpp"
#include "pipeline/schedule/rig_sensors.hpp"
#include "systems/aim_camera.hpp"
#include "systems/cast_lidar.hpp"
#include "systems/generate_terrain.hpp"
#include "systems/place_vegetation.hpp"
#include "systems/plan_captures.hpp"
#include "systems/prefetch_chunks.hpp"
#include "systems/prepare_scene.hpp"
#include "systems/resolve_overlaps.hpp"
#include "systems/store_chunks.hpp"
#include "systems/stream_chunks.hpp"
#include "world/chunk_cache.hpp"
#include "world/chunk_regions.hpp"
#include "world/world_context.hpp"

namespace silva::pipeline {

WorldSchedule::WorldSchedule(const world::WorldContext& ctx, std::size_t cache_capacity) {
  world_.set_resource(WorldSource{&ctx});
  world_.set_resource(world::ChunkCache(cache_capacity));
  world_.set_resource(PinnedChunks{});
  systems::install_plan_captures(world_, {});
  systems::install_aim_camera(world_);
  systems::install_stream_chunks(world_);
  systems::install_generate_terrain(world_);
  systems::install_place_vegetation(world_);
  systems::install_resolve_overlaps(world_);
  systems::install_store_chunks(world_);
  systems::install_prepare_scene(world_, *ctx.library);
  systems::install_prefetch_chunks(world_);
  systems::install_render_views(world_, {});
  systems::install_cast_lidar(world_, *ctx.library);
  systems::install_write_dataset(world_);
  world_.build_schedule();
}

const std::vector<world::PlannedFrame>& WorldSchedule::plan(std::vector<PoseEntry> custom_poses,
                                                          std::function<void(const std::string&)> warn) {
  auto& p = world_.resource<systems::CapturePlan>();
  p.custom_poses = std::move(custom_poses);
  p.warn = std::move(warn);
  world_.run_phases(Phase::Plan, Phase::Plan);
  return p.frames;
}

double WorldSchedule::last_seconds(std::initializer_list<const char*> names) const {
  double s = 0;
  for (const ecs::SystemStats& st : world_.system_stats())
    for (const char* n : names)
      if (st.name == n) s += double(st.last_ns) * 1e-9;
  return s;
}

void WorldSchedule::queue_cameras(const std::vector<world::PlannedFrame>& frames) {
  std::map<int, ecs::Entity> planned;
  if (world_.resource<systems::CapturePlan>().planned)
    world_.view<const world::PlannedFrame>().each(
        [&](ecs::Entity e, const world::PlannedFrame& f) { planned.emplace(f.global_index, e); });
  CaptureQueue& queue = world_.resource<CaptureQueue>();
  queue = CaptureQueue{};
  for (const world::PlannedFrame& f : frames)
    queue.cameras.push_back(planned.empty() ? world_.spawn(world::PlannedFrame(f)) : planned.at(f.global_index));
}

systems::CaptureStats WorldSchedule::capture(const std::vector<world::PlannedFrame>& frames,
                                             systems::CaptureSettings settings,
                                             const systems::ProgressFn& progress,
                                             const std::function<bool()>& stop) {
  const Stopwatch run_clock;
  queue_cameras(frames);
  CaptureQueue& queue = world_.resource<CaptureQueue>();
  systems::create_output_folders(settings.run_dir, frames, settings.outputs, settings.stereo_baseline_m > 0);
  mount_rig_sensors(world_, settings, world_.resource<WorldSource>().ctx->config.lidar);
  world_.resource<systems::CaptureSettings>() = std::move(settings);
  systems::DatasetWriter& writer = *world_.resource<std::unique_ptr<systems::DatasetWriter>>();
  writer.stats = {};
  writer.progress = progress;
  writer.total = int(frames.size());
  const size_t threads = std::min<size_t>(size_t(tbb::this_task_arena::max_concurrency()),
                                          tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
  writer.stage.set_limit(systems::frames_in_flight(threads) - 1);
  const world::ChunkCache& cache = world_.resource<world::ChunkCache>();
  const size_t generated_before = cache.generated();
  const std::vector<ecs::SystemStats> systems_before = world_.system_stats();
  double stream_s = 0, prepare_s = 0;
  bool stopped = false;
  while (queue.pending() && !writer.stage.failed()) {
    if (stop && stop()) {
      stopped = true;
      break;
    }
    world_.run_phases(Phase::Stream, Phase::Write);
    stream_s += last_seconds({"aim_camera", "stream_chunks", "generate_terrain", "place_vegetation",
                              "resolve_overlaps", "store_chunks"});
    prepare_s += last_seconds({"prepare_scene"});
  }
  writer.stage.finish();
  systems::CaptureStats stats = writer.stats;
  stats.stopped = stopped;
  stats.stream_s = stream_s;
  stats.prepare_s = prepare_s;
  stats.chunks_generated = cache.generated() - generated_before;
  stats.wall_s = run_clock.seconds();
  for (size_t i = 0; i < systems_before.size(); ++i) {
    const ecs::SystemStats& st = world_.system_stats()[i];
    stats.system_s.emplace_back(st.name, double(st.total_ns - systems_before[i].total_ns) * 1e-9);
  }
  return stats;
}

std::shared_ptr<systems::FrameWork> WorldSchedule::render_view(const world::PlannedFrame& frame,
                                                                systems::CaptureSettings settings) {
  if (view_camera_.is_null()) {
    view_camera_ = world_.spawn(world::PlannedFrame(frame));
  } else {
    world_.get<world::PlannedFrame>(view_camera_) = frame;
  }
  CaptureQueue& queue = world_.resource<CaptureQueue>();
  queue = CaptureQueue{};
  queue.cameras.push_back(view_camera_);
  mount_rig_sensors(world_, settings, world_.resource<WorldSource>().ctx->config.lidar);
  world_.resource<systems::CaptureSettings>() = std::move(settings);
  world_.run_phases(Phase::Stream, Phase::Render);
  return std::move(world_.resource<systems::FrameSlots>().current);
}

namespace {
/// `coords` sorted, without repeats.
std::vector<ChunkCoord> sorted_unique(std::vector<ChunkCoord> coords) {
  std::sort(coords.begin(), coords.end());
  coords.erase(std::unique(coords.begin(), coords.end()), coords.end());
  return coords;
}
}  // namespace

void WorldSchedule::stream_pinned(const std::vector<ChunkCoord>& coords, bool for_drawing) {
  world_.resource<CaptureQueue>() = CaptureQueue{};
  world_.resource<PinnedChunks>() = PinnedChunks{coords, for_drawing};
  world_.run_phases(Phase::Stream, Phase::Write);
  world_.resource<PinnedChunks>() = PinnedChunks{};
}

world::BuiltWorld WorldSchedule::build(std::vector<ChunkCoord> coords) {
  coords = sorted_unique(std::move(coords));
  stream_pinned(coords, false);
  world::BuiltWorld w = world::summarise_world(world_.resource<world::ChunkCache>().release(coords));
  w.totals.place_s = last_seconds({"place_vegetation"});
  w.totals.chunks_s = last_seconds({"generate_terrain", "resolve_overlaps"});
  return w;
}

world::WorldTotals WorldSchedule::warm(std::vector<ChunkCoord> coords) {
  coords = sorted_unique(std::move(coords));
  stream_pinned(coords, true);
  world::WorldTotals totals;
  const world::ChunkCache& cache = world_.resource<world::ChunkCache>();
  for (ChunkCoord c : coords) world::accumulate(totals, cache.find(c)->stats);
  return totals;
}

std::vector<std::shared_ptr<const ChunkContent>> WorldSchedule::chunks(const std::vector<ChunkCoord>& coords) {
  world::ChunkCache& cache = world_.resource<world::ChunkCache>();
  const std::vector<ChunkCoord> missing = cache.missing(coords);
  if (!missing.empty()) stream_pinned(missing, true);
  return cache.take(coords);
}

std::vector<std::shared_ptr<const ChunkContent>> ScheduleChunks::require(const world::WorldContext& /*ctx*/,
                                                                                const std::vector<ChunkCoord>& coords) {
  return schedule_->chunks(coords);
}

world::BuiltWorld build_world(const world::WorldContext& ctx, std::vector<ChunkCoord> coords, int threads) {
  const Stopwatch clock;
  world::BuiltWorld w;
  tbb::task_arena arena(std::max(1, threads));
  arena.execute([&] {
    WorldSchedule schedule(ctx, coords.size());
    w = schedule.build(std::move(coords));
  });
  w.totals.total_s = clock.seconds();
  return w;
}

world::BuiltWorld build_default_world(const world::WorldContext& ctx, int threads) {
  return build_world(ctx, world::default_world_chunks(ctx.config), threads);
}

}  // namespace silva::pipeline
