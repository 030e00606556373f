#pragma once
/// @file The Plan phase: every capture pose of a run, in global frame order (CONTRACT.md
/// "Capture sequences"): sequences in config order, then frame number within the sequence.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/camera.hpp"
#include "core/pose_entry.hpp"
#include "world/chunk_cache.hpp"
#include "world/world_context.hpp"

namespace silva::world {

/// One planned capture.
struct PlannedFrame {
  std::string sequence;           ///< "autopilot", "random" or "custom".
  int frame = 0;                  ///< Frame number within the sequence.
  int global_index = 0;           ///< Position in the run's global frame order (sharding key).
  bool aerial = false;            ///< Aerial perspective.
  Camera camera;                  ///< Intrinsics, pose, near/far.
  double yaw_deg = 0, pitch_deg = 0, roll_deg = 0;  ///< Pose angles (CONTRACT.md convention).
  std::optional<double> trail_s;  ///< Arc length along the trail (autopilot only).
};

/// Steepest slope a random pose may stand on (CONTRACT.md), degrees.
inline constexpr double kMaxWalkableSlopeDeg = 30.0;
/// Smallest distance from a random pose to any solid proxy (CONTRACT.md), metres.
inline constexpr double kPoseClearance = 0.5;
/// Random pose attempts before a frame is declared impossible.
inline constexpr int kMaxPoseAttempts = 10000;

/// Autopilot: n points evenly spaced by arc length over the whole nav spline, both ends
/// included, one frame per (point, yaw); frame = i * yaws + k. Empty when the trail is off.
std::vector<PlannedFrame> plan_autopilot(const WorldContext& ctx);

/// Random: captures.random_count poses in the capture region on walkable ground, clear of every
/// solid proxy, yaw uniform; frame f draws from the RNG keyed on (seed, f). Uses `cache` for
/// the chunks around each candidate. Throws InputError if no valid pose is found for a frame.
std::vector<PlannedFrame> plan_random(const WorldContext& ctx, ChunkCache& cache);

/// Custom: one frame per pose of the pose file, in file order (z omitted: ground height above terrain).
std::vector<PlannedFrame> plan_custom(const WorldContext& ctx, const std::vector<PoseEntry>& poses);

/// Every frame of the run: the sequences of captures.sequences in order, global indices assigned.
/// Autopilot is skipped with a warning (via `warn`) when the trail is off; InputError if nothing is left.
std::vector<PlannedFrame> plan_captures(const WorldContext& ctx, ChunkCache& cache,
                                        const std::vector<PoseEntry>& custom_poses,
                                        const std::function<void(const std::string&)>& warn);

/// True when a camera standing at (x, y) keeps kPoseClearance from every solid proxy of `chunks`
/// up to `height` above the ground, and the terrain slope there is walkable.
bool pose_is_clear(const WorldContext& ctx, const std::vector<std::shared_ptr<const ChunkContent>>& chunks,
                   double x, double y, double height);

}  // namespace silva::world
