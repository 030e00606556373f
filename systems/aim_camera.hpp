#pragma once
/// @file Stream phase, first step: the frame's camera and the chunks its view needs (system "aim_camera").
#include <vector>

#include "components/chunk.hpp"
#include "core/camera.hpp"
#include "core/types.hpp"
#include "ecs/world.hpp"
#include "world/plan_captures.hpp"

namespace silva::systems {

struct CaptureSettings;

/// The chunks a capture streams for a view: those meeting its frustum plus the disc whose objects
/// may cast shadows into it, or the disc out to `lidar_reach` (the LiDAR's max range; 0 without one)
/// when that is larger. What the frame's scene holds, so `silva verify` rebuilds exactly these.
std::vector<ChunkCoord> capture_chunks(const Camera& camera, double chunk_size, double lidar_reach);

/// The chunks frame `f` needs: capture_chunks of its camera and, when it has a fan, the union of
/// capture_chunks over the fan's views (sorted, unique).
ViewChunks frame_chunks(const world::PlannedFrame& f, double chunk_size, double lidar_reach);

/// How far around a view its LiDAR sees: the selected preset's max range, 0 without output type lidar.
double lidar_reach(const CaptureSettings& settings);

/// Registers "aim_camera" (phase Stream): makes the next camera of the CaptureQueue resource active
/// (none when the queue is done) and sets the ViewChunks resource to frame_chunks of its frame.
void install_aim_camera(ecs::World& world);

}  // namespace silva::systems
