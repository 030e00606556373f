#pragma once
/// @file The continuous walk of the `trajectory` sequence (CONTRACT.md "Capture sequences"): a camera
/// carried along the trail at trajectory.speed, its path and heading smoothed into C2 curves of time,
/// with a walking bob and sway, so that velocity, acceleration and angular velocity are exact.
#include <optional>
#include <utility>

#include "core/types.hpp"
#include "world/cubic_bspline.hpp"
#include "world/world_context.hpp"

namespace silva::world {

/// Gravity in the world frame (Z up), m/s².
inline constexpr double kGravity = 9.81;
/// Time between the walk's control points, seconds: the curves smooth out detail shorter than this.
inline constexpr double kTrajectoryKnotStep = 0.25;

/// Height above the ground and pitch (degrees) of autopilot, random and trajectory cameras: camera.aerial_height
/// and aerial_pitch_deg with captures.aerial (autopilot and random add the canopy under the eye:
/// plan_captures.hpp), else the rig's camera height (rig_camera_height) and its preset's tilt.
std::pair<double, double> camera_height_and_pitch(const Config& c);

/// The camera's state at one time of the walk.
struct RigState {
  double t = 0;                        ///< Seconds from the start.
  Vec3d position;                      ///< Camera centre, world metres.
  Vec3d velocity;                      ///< World m/s.
  Vec3d acceleration;                  ///< World m/s² (gravity not included).
  Mat3d rotation;                      ///< camera_to_world rotation (CONTRACT.md camera axes).
  Vec3d angular_velocity;              ///< In the camera's axes, rad/s.
  double yaw_deg = 0, pitch_deg = 0, roll_deg = 0;  ///< The pose angles (CONTRACT.md convention).
  std::optional<double> trail_s;       ///< Nominal arc length along the trail, metres (none: a walk from trajectory.file).
  /// camera_to_world of this state.
  Mat4d pose() const {
    Mat4d m = Mat4d::Identity();
    m.block<3, 3>(0, 0) = rotation;
    m.block<3, 1>(0, 3) = position;
    return m;
  }
};

/// The walk of a world's trajectory sequence: from trajectory.start_m along the trail, or through the poses of
/// trajectory.file (ctx.walk_poses).
class Trajectory {
 public:
  /// The walk of `ctx`: through ctx.walk_poses when it has any (smoothed into C2 curves with control points
  /// kTrajectoryKnotStep apart; no bob or sway added), else along the trail (trajectory.* keys,
  /// camera.ground_height or the aerial height and pitch; InputError naming the keys when it would run past the
  /// end of the trail; needs ctx.trail.enabled).
  explicit Trajectory(const WorldContext& ctx);
  /// The state at time t (0 ... duration()).
  RigState at(double t) const;
  /// trajectory.duration_s, or the span of trajectory.file's times.
  double duration() const { return duration_; }

 private:
  /// The walk of `ctx` with its curves (walk_curves in trajectory.cpp): position and yaw, pitch and roll or none.
  Trajectory(const WorldContext& ctx, std::pair<CubicBSpline, std::optional<CubicBSpline>> curves);

  double duration_, start_m_, speed_, pitch_deg_, bob_m_, sway_deg_, step_hz_;
  CubicBSpline curve_;  ///< x, y, z (without the bob), yaw in degrees (unwrapped).
  std::optional<CubicBSpline> attitude_;  ///< Pitch and roll in degrees of a walk from a file (none: on the trail).
};

}  // namespace silva::world
