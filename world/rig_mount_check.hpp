#pragma once
/// @file The rig's mount check: no camera of a rig may sit inside a solid object (a trunk, rock or log).
#include <vector>

#include "world/chunk_cache.hpp"
#include "world/plan_captures.hpp"
#include "world/world_context.hpp"

namespace silva::world {

/// Throws InputError (one line: the rig keys, the camera, sequence, frame, position and the object's kind) when a
/// camera the rig places is inside a solid collision proxy at any of `frames`: the right camera of a stereo pair
/// at every frame, and with two cameras or rig.height_m set the left camera of trajectory frames (autopilot and random
/// poses already keep captures.clearance). Does nothing for one camera at camera.ground_height.
void check_rig_mounts(const WorldContext& ctx, ChunkCache& cache, const std::vector<PlannedFrame>& frames);

}  // namespace silva::world
