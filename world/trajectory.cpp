#include "world/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/camera.hpp"
#include "core/error.hpp"
#include "core/rig_presets.hpp"
#include "world/terrain.hpp"

namespace silva::world {

namespace {

constexpr double kPi = 3.14159265358979323846;
/// Half the chord whose direction is the walk's heading, metres: the heading looks past bends
/// shorter than this.
constexpr double kHeadingChord = 1.5;

/// The trail's centre line at arc length s, continued straight past its ends.
Vec3d trail_point(const NavSpline& nav, double s) {
  const double c = std::clamp(s, 0.0, nav.length());
  return nav.position(c) + (s - c) * nav.tangent(c);
}

/// The walk's control points every kTrajectoryKnotStep seconds: the trail point at the nominal arc
/// length, the ground under it plus the camera height, and the heading of the trail's chord there
/// (degrees, unwrapped). InputError when the walk runs past the trail's end.
CubicBSpline walk_curve(const WorldContext& ctx) {
  const Config& c = ctx.config;
  const TrajectoryConfig& tc = c.trajectory;
  if (!ctx.trail.enabled) throw InputError("captures.sequences: trajectory follows the trail and trail.enabled = false");
  const double length = ctx.trail.nav.length(), end = tc.start_m + tc.speed * tc.duration_s;
  if (end > length)
    throw InputError("trajectory: start_m + speed x duration_s = " + std::to_string(end) +
                     " m runs past the end of the trail (" + std::to_string(length) +
                     " m long); lower trajectory.duration_s, speed or start_m, or lengthen the trail");
  const double height = camera_height_and_pitch(c).first;
  const size_t n = size_t(std::ceil(tc.duration_s / kTrajectoryKnotStep)) + 4;
  std::vector<Eigen::Vector4d> control;
  control.reserve(n);
  double previous_yaw = 0;
  for (size_t i = 0; i < n; ++i) {
    const double s = tc.start_m + tc.speed * (double(i) - 1.0) * kTrajectoryKnotStep;
    const Vec3d p = trail_point(ctx.trail.nav, s);
    const Vec3d chord = trail_point(ctx.trail.nav, s + kHeadingChord) - trail_point(ctx.trail.nav, s - kHeadingChord);
    double yaw = std::atan2(chord.y(), chord.x()) * 180.0 / kPi;
    if (i > 0) yaw = previous_yaw + std::remainder(yaw - previous_yaw, 360.0);
    previous_yaw = yaw;
    control.emplace_back(p.x(), p.y(), double(terrain_height(ctx.terrain, p.x(), p.y())) + height, yaw);
  }
  return {std::move(control), kTrajectoryKnotStep};
}

/// The pose of `poses` at time t: position linear and rotation spherical between neighbours; before the first
/// pose and after the last, the position continues at the end segment's velocity and the rotation stays.
std::pair<Vec3d, Mat3d> pose_at(const std::vector<TimedPose>& poses, double t) {
  const auto next = std::upper_bound(poses.begin() + 1, poses.end() - 1, t,
                                     [](double x, const TimedPose& p) { return x < p.t; });
  const TimedPose& a = *(next - 1);
  const TimedPose& b = *next;
  const double w = (t - a.t) / (b.t - a.t);
  const Vec3d position = a.position + w * (b.position - a.position);
  const Eigen::Quaterniond q = Eigen::Quaterniond(a.rotation).slerp(std::clamp(w, 0.0, 1.0), Eigen::Quaterniond(b.rotation));
  return {position, q.toRotationMatrix()};
}

/// Control points every kTrajectoryKnotStep seconds through a file's poses: x, y, z, yaw and pitch, roll, 0, 0
/// (degrees; yaw and roll unwrapped).
std::pair<CubicBSpline, CubicBSpline> file_curves(const std::vector<TimedPose>& poses) {
  const double span = poses.back().t - poses.front().t;
  const size_t n = size_t(std::ceil(span / kTrajectoryKnotStep)) + 4;
  std::vector<Eigen::Vector4d> path, attitude;
  for (size_t i = 0; i < n; ++i) {
    const auto [p, r] = pose_at(poses, poses.front().t + (double(i) - 1.0) * kTrajectoryKnotStep);
    Vec3d angles = angles_from_rotation(r);
    if (i > 0) {
      angles.x() = path.back()[3] + std::remainder(angles.x() - path.back()[3], 360.0);
      angles.z() = attitude.back()[1] + std::remainder(angles.z() - attitude.back()[1], 360.0);
    }
    path.emplace_back(p.x(), p.y(), p.z(), angles.x());
    attitude.emplace_back(angles.y(), angles.z(), 0.0, 0.0);
  }
  return {CubicBSpline(std::move(path), kTrajectoryKnotStep), CubicBSpline(std::move(attitude), kTrajectoryKnotStep)};
}

/// The walk's position and yaw curve, and its pitch and roll curve when it goes through ctx.walk_poses (none: along
/// the trail).
std::pair<CubicBSpline, std::optional<CubicBSpline>> walk_curves(const WorldContext& ctx) {
  if (ctx.walk_poses.empty()) return {walk_curve(ctx), std::nullopt};
  auto [path, attitude] = file_curves(ctx.walk_poses);
  return {std::move(path), std::move(attitude)};
}

}  // namespace

std::pair<double, double> camera_height_and_pitch(const Config& c) {
  return c.captures.aerial ? std::pair{c.camera.aerial_height, c.camera.aerial_pitch_deg}
                           : std::pair{rig_camera_height(c), c.rig.pitch_deg};
}

Trajectory::Trajectory(const WorldContext& ctx) : Trajectory(ctx, walk_curves(ctx)) {}

Trajectory::Trajectory(const WorldContext& ctx, std::pair<CubicBSpline, std::optional<CubicBSpline>> curves)
    : duration_(ctx.walk_poses.empty() ? ctx.config.trajectory.duration_s
                                       : ctx.walk_poses.back().t - ctx.walk_poses.front().t),
      start_m_(ctx.config.trajectory.start_m),
      speed_(ctx.config.trajectory.speed),
      pitch_deg_(camera_height_and_pitch(ctx.config).second),
      bob_m_(ctx.config.trajectory.bob_m),
      sway_deg_(ctx.config.trajectory.sway_deg),
      step_hz_(ctx.config.trajectory.step_hz),
      curve_(std::move(curves.first)),
      attitude_(std::move(curves.second)) {}

RigState Trajectory::at(double t) const {
  const CubicBSpline::Sample c = curve_.at(t);
  const double w = 2.0 * kPi * step_hz_;  // the bob's angular frequency; the sway's is half
  RigState s;
  s.t = t;
  double pitch_rate = 0, roll_rate = 0;  // degrees per second
  if (attitude_) {
    const CubicBSpline::Sample a = attitude_->at(t);
    s.position = c.value.head<3>();
    s.velocity = c.rate.head<3>();
    s.acceleration = c.acceleration.head<3>();
    s.pitch_deg = a.value[0];
    s.roll_deg = a.value[1];
    pitch_rate = a.rate[0];
    roll_rate = a.rate[1];
  } else {
    s.position = Vec3d(c.value[0], c.value[1], c.value[2] + bob_m_ * std::sin(w * t));
    s.velocity = Vec3d(c.rate[0], c.rate[1], c.rate[2] + bob_m_ * w * std::cos(w * t));
    s.acceleration = Vec3d(c.acceleration[0], c.acceleration[1], c.acceleration[2] - bob_m_ * w * w * std::sin(w * t));
    s.pitch_deg = pitch_deg_;
    s.roll_deg = sway_deg_ * std::sin(0.5 * w * t);
    roll_rate = sway_deg_ * 0.5 * w * std::cos(0.5 * w * t);
    s.trail_s = start_m_ + speed_ * t;
  }
  s.yaw_deg = c.value[3];
  const double yaw_rate = c.rate[3];
  s.rotation = rotation_from_angles(s.yaw_deg, s.pitch_deg, s.roll_deg);
  // R = Rz(yaw) Ry(-pitch) Rx(roll) B turns at yaw' about the world's Z, at -pitch' about Rz Y and at roll' about
  // the axis Rz Ry X.
  const double to_rad = kPi / 180.0;
  const Eigen::AngleAxisd yaw(s.yaw_deg * to_rad, Vec3d::UnitZ());
  const Mat3d yaw_pitch = (yaw * Eigen::AngleAxisd(-s.pitch_deg * to_rad, Vec3d::UnitY())).toRotationMatrix();
  Vec3d omega_world = to_rad * (yaw_rate * Vec3d::UnitZ() + roll_rate * (yaw_pitch * Vec3d::UnitX()));
  if (attitude_) omega_world -= to_rad * pitch_rate * (yaw * Vec3d::UnitY());
  s.angular_velocity = s.rotation.transpose() * omega_world;
  return s;
}

}  // namespace silva::world
