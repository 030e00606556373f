#pragma once
/// @file The one schedule every world-building command runs: an ECS world with every system
/// registered (Plan once; per frame Stream -> Generate -> Place -> Resolve -> Prepare -> Render
/// -> Write), and the loops `silva generate`, `silva world` and `silva profile` drive it with.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/pose_entry.hpp"
#include "ecs/world.hpp"
#include "systems/render_views.hpp"
#include "systems/write_dataset.hpp"
#include "world/chunk_cache.hpp"
#include "world/plan_captures.hpp"
#include "world/world_context.hpp"
#include "world/world_summary.hpp"

namespace silva::pipeline {

/// The ECS world of one command run, with the schedule installed. Holds a pointer to `ctx`,
/// which must outlive it.
class WorldSchedule {
 public:
  /// Registers every system; the chunk cache keeps at most `cache_capacity` chunks between frames.
  WorldSchedule(const world::WorldContext& ctx, std::size_t cache_capacity);

  /// Runs the Plan phase: every capture pose (custom poses from `custom_poses`), one camera entity
  /// each. Returns the planned frames in global order.
  const std::vector<world::PlannedFrame>& plan(std::vector<PoseEntry> custom_poses,
                                               std::function<void(const std::string&)> warn);

  /// Captures `frames` in order, one schedule frame each, until done or `stop()` turns true
  /// between frames. After plan(), `frames` must be planned ones (their camera entities are
  /// used, matched by global index); without a plan, a camera entity is spawned for each.
  systems::CaptureStats capture(const std::vector<world::PlannedFrame>& frames, systems::CaptureSettings settings,
                                const systems::ProgressFn& progress, const std::function<bool()>& stop);

  /// Runs one schedule frame for `frame` through Stream .. Render (no Write: nothing is written)
  /// with `settings`, and returns the rendered slot (G-buffer, and the shadow map when rgb is
  /// selected; RGB not shaded yet: systems::shade_frame). One camera entity serves every call.
  std::shared_ptr<systems::FrameWork> render_view(const world::PlannedFrame& frame, systems::CaptureSettings settings);

  /// Runs one schedule frame with `coords` pinned and no camera, and returns those chunks (moved
  /// out of the chunk cache).
  world::BuiltWorld build(std::vector<ChunkCoord> coords);

  /// Runs one schedule frame with `coords` pinned and no camera, leaving the chunks in the cache
  /// ready for views (with their coarse terrain level); returns their totals (timings left zero).
  world::WorldTotals warm(std::vector<ChunkCoord> coords);

  /// The drawable chunks of `coords`, in that order, marked recently used (world::ChunkCache::take): those the
  /// cache lacks streamed by the schedule's systems in one schedule frame with them pinned and no camera.
  std::vector<std::shared_ptr<const ChunkContent>> chunks(const std::vector<ChunkCoord>& coords);

  /// The ECS world (its resources, entities and system timings).
  ecs::World& ecs() { return world_; }

 private:
  /// Seconds of the latest call of the systems named.
  double last_seconds(std::initializer_list<const char*> names) const;
  /// Runs one schedule frame streaming the sorted, unique `coords` and no camera.
  void stream_pinned(const std::vector<ChunkCoord>& coords, bool for_drawing);
  /// Fills the CaptureQueue with the camera entities of `frames`.
  void queue_cameras(const std::vector<world::PlannedFrame>& frames);

  ecs::World world_;
  ecs::Entity view_camera_ = ecs::null_entity;  ///< The camera entity render_view reuses.
};

/// Builds `coords` through the schedule on `threads` TBB threads; timings in the totals.
world::BuiltWorld build_world(const world::WorldContext& ctx, std::vector<ChunkCoord> coords, int threads);

/// build_world over world::default_world_chunks(ctx.config).
world::BuiltWorld build_default_world(const world::WorldContext& ctx, int threads);

/// A WorldSchedule as a chunk source (WorldSchedule::chunks) for code that asks for chunks between schedule
/// frames: a pose's clearance in `silva view`, the frames `silva verify` casts against.
class ScheduleChunks final : public world::ChunkSource {
 public:
  /// Asks `schedule`, which must outlive this.
  explicit ScheduleChunks(WorldSchedule& schedule) : schedule_(&schedule) {}
  /// The schedule's chunks of `coords` (the context is the schedule's own).
  std::vector<std::shared_ptr<const ChunkContent>> require(const world::WorldContext& ctx,
                                                                  const std::vector<ChunkCoord>& coords) override;

 private:
  WorldSchedule* schedule_;
};

}  // namespace silva::pipeline
