#pragma once
/// @file Plan phase: every capture pose of the run, once, as camera entities (system "plan_captures").
#include <functional>
#include <string>
#include <vector>

#include "core/pose_entry.hpp"
#include "ecs/world.hpp"
#include "world/plan_captures.hpp"

namespace silva::systems {

/// Resource: what planning reads (custom poses, a warning sink) and what it produced.
struct CapturePlan {
  std::vector<PoseEntry> custom_poses;                  ///< Poses of the custom sequence.
  std::function<void(const std::string&)> warn;         ///< Receives planning warnings.
  std::vector<world::PlannedFrame> frames;              ///< Every planned frame, in global order.
  bool planned = false;                                 ///< True once the Plan phase has run.
};

/// Registers "plan_captures" (phase Plan): world::plan_captures over the WorldSource (random poses
/// look at chunks through the ChunkCache resource), fills CapturePlan::frames and spawns one camera
/// entity (a world::PlannedFrame component) per frame. Runs its work once.
void install_plan_captures(ecs::World& world, CapturePlan plan);

}  // namespace silva::systems
