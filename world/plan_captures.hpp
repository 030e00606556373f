#pragma once
/// @file The Plan phase: every capture pose of a run, in global frame order (CONTRACT.md
/// "Capture sequences"): sequences in config order, then frame number within the sequence.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/camera.hpp"
#include "core/camera_model.hpp"
#include "core/pose_entry.hpp"
#include "world/chunk_cache.hpp"
#include "world/world_context.hpp"

namespace silva::world {

class Trajectory;

/// How a planned autopilot or random pose met the clearance rules (world/pose_clearance.hpp).
enum class PoseFix : uint8_t {
  Clear,         ///< Clear where it was planned (custom poses are never checked).
  Moved,         ///< Moved by the search (autopilot: along the trail; random: a spiral around its draw).
  Unresolvable,  ///< No clear pose within the search: kept where it was planned.
};

/// One planned capture.
struct PlannedFrame {
  std::string sequence;           ///< "autopilot", "random", "custom" or "trajectory".
  int frame = 0;                  ///< Frame number within the sequence.
  int global_index = 0;           ///< Position in the run's global frame order (sharding key).
  bool aerial = false;            ///< Aerial perspective.
  Camera camera;                  ///< Intrinsics, pose, near/far.
  double yaw_deg = 0, pitch_deg = 0, roll_deg = 0;  ///< Pose angles (CONTRACT.md convention).
  /// Yaws of every frame taken from this frame's position (an autopilot point: one per configured yaw, this
  /// frame's among them), which share one sun shadow map; empty for a frame alone at its position.
  std::vector<double> fan_yaws_deg;
  std::optional<double> trail_s;  ///< Arc length along the trail (autopilot and trajectory only).
  PoseFix pose_fix = PoseFix::Clear;  ///< Whether the clearance search moved the pose.
  std::optional<ExposureMotion> exposure_motion;  ///< Camera motion while the shutter is open (motion blur), or still.
  std::shared_ptr<const Trajectory> walk;  ///< The walk a trajectory frame lies on (one for all of them), else null.
  bool right = false;             ///< The right camera of a stereo pair (false: the mono or left camera).
};

/// Steepest slope a random pose may stand on (CONTRACT.md), degrees.
inline constexpr double kMaxWalkableSlopeDeg = 30.0;
/// Random pose draws before a frame is declared impossible (no walkable ground).
inline constexpr int kMaxPoseAttempts = 10000;
/// Walkable random draws searched around (a spiral each) before a random pose is unresolvable.
inline constexpr int kMaxClearanceDraws = 16;
/// Step (metres) of the clearance searches: along the trail, and between the spiral's rings.
inline constexpr double kPoseSearchStep = 0.5;
/// Farthest an autopilot pose moves along the trail (metres) to find clearance.
inline constexpr double kTrailSearchReach = 20.0;
/// Rings of the spiral around a random draw (radius kSpiralRings * kPoseSearchStep).
inline constexpr int kSpiralRings = 8;
/// Horizontal distance (metres) within which a tree crown lies under an aerial camera: its eye keeps
/// camera.aerial_height above the top of every such crown.
inline constexpr double kAerialCanopyMargin = 5.0;

/// Autopilot: n points evenly spaced by arc length over the whole nav spline, both ends
/// included, one frame per (point, yaw); frame = i * yaws + k. Empty when the trail is off.
/// The trail's own poses, before settle_autopilot.
std::vector<PlannedFrame> plan_autopilot(const WorldContext& ctx);

/// Moves each autopilot point that is not clear (pose_clearance.hpp) to the nearest clear arc
/// length within kTrailSearchReach (tried in steps of kPoseSearchStep, ahead first), keeping
/// its yaws relative to the trail; marks the frames Moved or Unresolvable (left in place).
void settle_autopilot(const WorldContext& ctx, ChunkCache& cache, std::vector<PlannedFrame>& frames);

/// The camera-to-world pose of autopilot frame `f` moved `distance` metres along the trail (negative: back;
/// kept within the trail), its yaw relative to the trail and its height above the trail's ground as before (an
/// aerial eye keeps its lift above the canopy): where the camera is
/// distance / camera.autopilot_speed seconds after (or before) the frame.
Mat4d autopilot_pose_along(const WorldContext& ctx, const PlannedFrame& f, double distance);

/// The camera-to-world pose of autopilot or trajectory frame `f` (it has trail_s) one LiDAR revolution
/// (1 / rotation_hz seconds) after the frame: along its walk for trajectory frames, else autopilot_pose_along
/// by camera.autopilot_speed / rotation_hz metres.
Mat4d sweep_end_pose(const WorldContext& ctx, const PlannedFrame& f, double rotation_hz);

/// Gives each autopilot frame its motion while the shutter is open: the poses along the trail at
/// trail_s -/+ camera.autopilot_speed * camera.shutter_s / 2 (kept within the trail), yaws relative to it.
void add_autopilot_motion(const WorldContext& ctx, std::vector<PlannedFrame>& frames);

/// Random: captures.random_count poses in the capture region on walkable ground, yaw uniform;
/// frame f draws from the RNG keyed on (seed, f) until a walkable spot, then takes the first
/// clear spot of a spiral around it (the draw itself first; Moved when not the draw), drawing
/// again up to kMaxClearanceDraws times; if none is clear, the first walkable draw is kept as
/// Unresolvable. Uses `cache` for the chunks around each draw. Throws InputError if no
/// walkable spot is found in kMaxPoseAttempts draws.
std::vector<PlannedFrame> plan_random(const WorldContext& ctx, ChunkCache& cache);

/// Custom: one frame per pose of the pose file, in file order (z omitted: ground height above terrain).
std::vector<PlannedFrame> plan_custom(const WorldContext& ctx, const std::vector<PoseEntry>& poses);

/// Trajectory: llround(trajectory.duration_s x camera_hz) frames (at least one) of the walk (world/trajectory.hpp)
/// at i / camera_hz seconds, trail_s its nominal arc length, with camera.motion_blur the walk's poses when the
/// shutter opens and closes; no clearance search (the trail is kept clear).
/// InputError when the walk runs past the trail's end (the config's ranges keep it within 432 000 frames).
std::vector<PlannedFrame> plan_trajectory(const WorldContext& ctx);

/// Marks each trajectory frame of `frames` Clear or, when its camera is inside a solid collision proxy (within
/// camera.near; the walk is never moved), Unresolvable, and warns once through `warn` with their count and the first.
void check_walk(const WorldContext& ctx, ChunkCache& cache, std::vector<PlannedFrame>& frames,
                const std::function<void(const std::string&)>& warn);

/// Every frame of the run (autopilot settled): the sequences of captures.sequences in order, global indices assigned.
/// Autopilot is skipped with a warning (via `warn`) when the trail is off; InputError if nothing is left or a
/// camera of the rig is inside a solid object (check_rig_mounts).
std::vector<PlannedFrame> plan_captures(const WorldContext& ctx, ChunkCache& cache,
                                        const std::vector<PoseEntry>& custom_poses,
                                        const std::function<void(const std::string&)>& warn);

/// True when the terrain slope at (x, y) is at most kMaxWalkableSlopeDeg.
bool walkable(const WorldContext& ctx, double x, double y);

}  // namespace silva::world
