#include "world/plan_captures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "core/rig_presets.hpp"
#include "core/rng.hpp"
#include "world/parallel_plan.hpp"
#include "world/pose_clearance.hpp"
#include "world/rig_mount_check.hpp"
#include "world/terrain.hpp"
#include "world/trajectory.hpp"

namespace silva::world {

namespace {
constexpr double kDegPerRad = 180.0 / 3.14159265358979323846;

/// A camera of the run's resolution and lens at a pose given by position and angles.
PlannedFrame make_frame(const WorldContext& ctx, const std::string& sequence, int frame, const Vec3d& position,
                        double yaw, double pitch, double roll, bool aerial) {
  const Config& c = ctx.config;
  PlannedFrame f;
  f.sequence = sequence;
  f.frame = frame;
  f.aerial = aerial;
  f.camera = Camera::from_fov(c.output.width, c.output.height, c.camera.fov_deg, c.camera.near, c.camera.far);
  f.camera.camera_to_world = pose_from_angles(position, yaw, pitch, roll);
  f.yaw_deg = yaw;
  f.pitch_deg = pitch;
  f.roll_deg = roll;
  return f;
}

/// Wraps an angle in degrees to (-180, 180].
double wrap_degrees(double a) {
  a = std::fmod(a, 360.0);
  if (a > 180.0) a -= 360.0;
  if (a <= -180.0) a += 360.0;
  return a;
}

/// The autopilot frame for point i, yaw k, at arc length s.
PlannedFrame autopilot_frame(const WorldContext& ctx, int i, size_t k, double s) {
  const Config& c = ctx.config;
  const auto [height, pitch] = camera_height_and_pitch(c);
  const auto& yaws = c.captures.autopilot_yaws;
  const Vec3d p = ctx.trail.nav.position(s);
  const Vec3d t = ctx.trail.nav.tangent(s);
  const double heading = std::atan2(t.y(), t.x()) * kDegPerRad;
  const double ground = terrain_height(ctx.terrain, p.x(), p.y());
  PlannedFrame f = make_frame(ctx, "autopilot", int(i * yaws.size() + k), Vec3d(p.x(), p.y(), ground + height),
                              wrap_degrees(heading + yaws[k]), pitch, 0.0, c.captures.aerial);
  f.trail_s = s;
  for (const double yaw : yaws) f.fan_yaws_deg.push_back(wrap_degrees(heading + yaw));
  return f;
}

/// Eye height at (x, y): the camera's height above the ground, or for aerial captures
/// camera.aerial_height above the top of the canopy within kAerialCanopyMargin (above the ground
/// where no crown reaches); `probe` must hold the trees around (x, y).
double eye_z(const WorldContext& ctx, const ClearanceProbe& probe, double x, double y) {
  const double ground = terrain_height(ctx.terrain, x, y), height = camera_height_and_pitch(ctx.config).first;
  if (!ctx.config.captures.aerial) return ground + height;
  return std::max(ground, probe.canopy_top(x, y, kAerialCanopyMargin)) + height;
}

/// Search radius of a probe that must also see the crowns over an aerial eye.
double probe_radius(const WorldContext& ctx, double radius) {
  return ctx.config.captures.aerial ? radius + kAerialCanopyMargin : radius;
}

/// Offsets of the spiral around a random draw: ring by ring outwards, the draw itself first.
const std::vector<Eigen::Vector2d>& spiral_offsets() {
  static const std::vector<Eigen::Vector2d> offsets = [] {
    std::vector<Eigen::Vector2d> out = {Eigen::Vector2d::Zero()};
    for (int ring = 1; ring <= kSpiralRings; ++ring)
      for (int j = 0; j < 8 * ring; ++j) {
        const double a = 2.0 * 3.14159265358979323846 * double(j) / double(8 * ring);
        out.emplace_back(double(ring) * kPoseSearchStep * std::cos(a), double(ring) * kPoseSearchStep * std::sin(a));
      }
    return out;
  }();
  return offsets;
}

/// The first clear spot of the spiral around (x, y) inside the capture region on walkable
/// ground: its offset index and eye, or index -1.
std::pair<int, Vec3d> clear_spiral_spot(const WorldContext& ctx, ChunkSource& chunks, const CrownProfiles& crowns,
                                        double x, double y) {
  const double radius = kSpiralRings * kPoseSearchStep, half = 0.5 * ctx.config.world.extent;
  const ClearanceProbe probe = ClearanceProbe::around(ctx, chunks, crowns, x, y, probe_radius(ctx, radius));
  const auto& offsets = spiral_offsets();
  for (size_t k = 0; k < offsets.size(); ++k) {
    const double cx = x + offsets[k].x(), cy = y + offsets[k].y();
    if (std::abs(cx) > half || std::abs(cy) > half || !walkable(ctx, cx, cy)) continue;
    const Vec3d eye(cx, cy, eye_z(ctx, probe, cx, cy));
    if (probe.clear(eye, ctx.config.captures.aerial)) return {int(k), eye};
  }
  return {-1, Vec3d::Zero()};
}
}  // namespace

bool walkable(const WorldContext& ctx, double x, double y) {
  const Vec3f n = terrain_normal(ctx.terrain, x, y);
  return std::acos(std::clamp(double(n.z()), -1.0, 1.0)) * kDegPerRad <= kMaxWalkableSlopeDeg;
}

std::vector<PlannedFrame> plan_autopilot(const WorldContext& ctx) {
  std::vector<PlannedFrame> frames;
  if (!ctx.trail.enabled) return frames;
  const int n = ctx.config.captures.autopilot_points;
  const double length = ctx.trail.nav.length();
  for (int i = 0; i < n; ++i) {
    const double s = n == 1 ? 0.0 : double(i) * length / double(n - 1);
    for (size_t k = 0; k < ctx.config.captures.autopilot_yaws.size(); ++k) frames.push_back(autopilot_frame(ctx, i, k, s));
  }
  return frames;
}

namespace {
/// Lifts the frames of the autopilot point whose first frame is `first` to their eye height, or moves them
/// along the trail to the nearest clear spot within kTrailSearchReach (PoseFix::Unresolvable when none).
void settle_point(const WorldContext& ctx, ChunkSource& chunks, const CrownProfiles& crowns,
                  std::vector<PlannedFrame>& frames, size_t first) {
  const size_t yaws = ctx.config.captures.autopilot_yaws.size();
  const double length = ctx.trail.nav.length();
  const bool aerial = ctx.config.captures.aerial;
  const auto lift = [&](double z) {
    for (size_t k = 0; k < yaws; ++k) frames[first + k].camera.camera_to_world(2, 3) = z;
  };
  const double s0 = *frames[first].trail_s;
  const Vec3d trail_eye = frames[first].camera.position();
  const ClearanceProbe here =
      ClearanceProbe::around(ctx, chunks, crowns, trail_eye.x(), trail_eye.y(), probe_radius(ctx, 0.0));
  const Vec3d eye(trail_eye.x(), trail_eye.y(), eye_z(ctx, here, trail_eye.x(), trail_eye.y()));
  lift(eye.z());
  if (here.clear(eye, aerial)) return;
  const ClearanceProbe probe =
      ClearanceProbe::around(ctx, chunks, crowns, eye.x(), eye.y(), probe_radius(ctx, kTrailSearchReach));
  std::optional<Vec3d> found;  // arc length, -, eye height
  for (int step = 1; step <= int(kTrailSearchReach / kPoseSearchStep) && !found; ++step)
    for (const double s : {s0 + step * kPoseSearchStep, s0 - step * kPoseSearchStep}) {
      if (s < 0.0 || s > length) continue;
      const Vec3d p = ctx.trail.nav.position(s);
      const double z = eye_z(ctx, probe, p.x(), p.y());
      if (probe.clear(Vec3d(p.x(), p.y(), z), aerial)) {
        found = Vec3d(s, 0.0, z);
        break;
      }
    }
  for (size_t k = 0; k < yaws; ++k) {
    PlannedFrame& f = frames[first + k];
    if (found) f = autopilot_frame(ctx, f.frame / int(yaws), k, found->x());
    f.pose_fix = found ? PoseFix::Moved : PoseFix::Unresolvable;
  }
  if (found) lift(found->z());
}
}  // namespace

void settle_autopilot(const WorldContext& ctx, ChunkCache& cache, std::vector<PlannedFrame>& frames) {
  const CrownProfiles crowns(*ctx.library);
  const size_t yaws = ctx.config.captures.autopilot_yaws.size();
  plan_in_parallel(cache, yaws == 0 ? 0 : frames.size() / yaws,
                   [&](size_t point, ChunkSource& chunks) { settle_point(ctx, chunks, crowns, frames, point * yaws); });
}

Mat4d autopilot_pose_along(const WorldContext& ctx, const PlannedFrame& f, double distance) {
  const int yaws = int(ctx.config.captures.autopilot_yaws.size());
  const double s = std::clamp(*f.trail_s + distance, 0.0, ctx.trail.nav.length());
  const auto trail_pose = [&](double at) {
    return autopilot_frame(ctx, f.frame / yaws, size_t(f.frame % yaws), at).camera.camera_to_world;
  };
  Mat4d pose = trail_pose(s);
  pose(2, 3) += f.camera.camera_to_world(2, 3) - trail_pose(*f.trail_s)(2, 3);  // an aerial eye's lift
  return pose;
}

void add_autopilot_motion(const WorldContext& ctx, std::vector<PlannedFrame>& frames) {
  const Config& c = ctx.config;
  const double half = 0.5 * c.camera.autopilot_speed * c.camera.shutter_s;
  for (PlannedFrame& f : frames)
    f.exposure_motion = ExposureMotion{c.camera.shutter_s, autopilot_pose_along(ctx, f, -half),
                                       autopilot_pose_along(ctx, f, half)};
}

namespace {
/// Random frame `f`: the first walkable draw of its own random stream with a clear spot on its spiral, else
/// the first walkable draw as drawn (PoseFix::Unresolvable).
PlannedFrame random_frame(const WorldContext& ctx, ChunkSource& chunks, const CrownProfiles& crowns, int f) {
  const Config& c = ctx.config;
  const auto [height, pitch] = camera_height_and_pitch(c);
  const double half = 0.5 * c.world.extent;
  Rng rng(uint64_t(c.seed), uint64_t(f), Purpose::RandomPose);
  std::optional<Vec3d> first;  // x, y, yaw of the first walkable draw
  int draws = 0;
  for (int attempt = 0; attempt < kMaxPoseAttempts && draws < kMaxClearanceDraws; ++attempt) {
    const double x = rng.range(float(-half), float(half));
    const double y = rng.range(float(-half), float(half));
    const double yaw = rng.range(-180.0f, 180.0f);
    if (!walkable(ctx, x, y)) continue;
    if (!first) first = Vec3d(x, y, yaw);
    ++draws;
    const auto [spot, eye] = clear_spiral_spot(ctx, chunks, crowns, x, y);
    if (spot < 0) continue;
    PlannedFrame frame = make_frame(ctx, "random", f, eye, yaw, pitch, 0.0, c.captures.aerial);
    frame.pose_fix = draws == 1 && spot == 0 ? PoseFix::Clear : PoseFix::Moved;
    return frame;
  }
  if (!first)
    throw InputError("captures.random_count: found no walkable pose for random frame " + std::to_string(f) + " in " +
                     std::to_string(kMaxPoseAttempts) + " tries; enlarge world.extent or lower terrain.max_elevation");
  const Vec3d p = *first;
  PlannedFrame frame = make_frame(ctx, "random", f, Vec3d(p.x(), p.y(), terrain_height(ctx.terrain, p.x(), p.y()) + height),
                                  p.z(), pitch, 0.0, c.captures.aerial);
  frame.pose_fix = PoseFix::Unresolvable;
  return frame;
}
}  // namespace

std::vector<PlannedFrame> plan_random(const WorldContext& ctx, ChunkCache& cache) {
  const CrownProfiles crowns(*ctx.library);
  std::vector<PlannedFrame> frames(size_t(std::max(0, ctx.config.captures.random_count)));
  plan_in_parallel(cache, frames.size(), [&](size_t f, ChunkSource& chunks) {
    frames[f] = random_frame(ctx, chunks, crowns, int(f));
  });
  return frames;
}

std::vector<PlannedFrame> plan_custom(const WorldContext& ctx, const std::vector<PoseEntry>& poses) {
  std::vector<PlannedFrame> frames;
  for (size_t i = 0; i < poses.size(); ++i) {
    const PoseEntry& p = poses[i];
    Vec3d position = p.position;
    if (!p.has_z) position.z() = terrain_height(ctx.terrain, p.position.x(), p.position.y()) + rig_camera_height(ctx.config);
    PlannedFrame f = make_frame(ctx, "custom", int(i), position, p.yaw_deg, p.pitch_deg, p.roll_deg, false);
    f.camera.camera_to_world.block<3, 3>(0, 0) = p.rotation;  // exact matrix when the file gave one
    frames.push_back(std::move(f));
  }
  return frames;
}

std::vector<PlannedFrame> plan_trajectory(const WorldContext& ctx) {
  const auto walk = std::make_shared<const Trajectory>(ctx);
  const TrajectoryConfig& tc = ctx.config.trajectory;
  const auto n = std::max<int64_t>(1, std::llround(walk->duration() * tc.camera_hz));
  std::vector<PlannedFrame> frames;
  frames.reserve(size_t(n));
  for (int64_t i = 0; i < n; ++i) {
    const double t = double(i) / tc.camera_hz;
    const RigState s = walk->at(t);
    PlannedFrame f = make_frame(ctx, "trajectory", int(i), s.position, s.yaw_deg, s.pitch_deg, s.roll_deg,
                                ctx.config.captures.aerial);
    f.trail_s = s.trail_s;
    if (ctx.config.camera.motion_blur) {
      const double shutter = ctx.config.camera.shutter_s;
      f.exposure_motion = ExposureMotion{shutter, walk->at(t - 0.5 * shutter).pose(), walk->at(t + 0.5 * shutter).pose()};
    }
    f.walk = walk;
    frames.push_back(std::move(f));
  }
  return frames;
}

void check_walk(const WorldContext& ctx, ChunkCache& cache, std::vector<PlannedFrame>& frames,
                const std::function<void(const std::string&)>& warn) {
  const CrownProfiles crowns(*ctx.library);
  plan_in_parallel(cache, frames.size(), [&](size_t i, ChunkSource& chunks) {
    PlannedFrame& f = frames[i];
    const Vec3d eye = f.camera.position();
    const ClearanceProbe probe = ClearanceProbe::around(ctx, chunks, crowns, eye.x(), eye.y(), 0.0);
    f.pose_fix = probe.solid_at(eye, ctx.config.camera.near) ? PoseFix::Unresolvable : PoseFix::Clear;
  });
  const PlannedFrame* first = nullptr;
  int blocked = 0;
  for (const PlannedFrame& f : frames) {
    if (f.pose_fix == PoseFix::Clear) continue;
    if (!first) first = &f;
    ++blocked;
  }
  if (!first) return;
  char text[320];
  std::snprintf(text, sizeof text,
                "trajectory: the camera is inside a solid object (a trunk, rock or log) in %d of %zu frames (first: "
                "frame %d, %.2f s), where bark fills the view; another trajectory.start_m or seed avoids them",
                blocked, frames.size(), first->frame,
                double(first->frame) / ctx.config.trajectory.camera_hz);
  warn(text);
}

Mat4d sweep_end_pose(const WorldContext& ctx, const PlannedFrame& f, double rotation_hz) {
  if (f.walk) return f.walk->at(double(f.frame) / ctx.config.trajectory.camera_hz + 1.0 / rotation_hz).pose();
  return autopilot_pose_along(ctx, f, ctx.config.camera.autopilot_speed / rotation_hz);
}

std::vector<PlannedFrame> plan_captures(const WorldContext& ctx, ChunkCache& cache,
                                        const std::vector<PoseEntry>& custom_poses,
                                        const std::function<void(const std::string&)>& warn) {
  std::vector<PlannedFrame> all;
  for (const std::string& sequence : ctx.config.captures.sequences) {
    std::vector<PlannedFrame> frames;
    if (sequence == "autopilot") {
      if (!ctx.trail.enabled) {
        warn("autopilot skipped: it follows the trail and trail.enabled = false");
        continue;
      }
      frames = plan_autopilot(ctx);
      settle_autopilot(ctx, cache, frames);
      if (ctx.config.camera.motion_blur) add_autopilot_motion(ctx, frames);
    } else if (sequence == "random") {
      frames = plan_random(ctx, cache);
    } else if (sequence == "custom") {
      frames = plan_custom(ctx, custom_poses);
    } else if (sequence == "trajectory") {
      if (!ctx.trail.enabled && ctx.walk_poses.empty()) {
        warn("trajectory skipped: it walks along the trail (no trajectory.file) and trail.enabled = false");
        continue;
      }
      frames = plan_trajectory(ctx);
      check_walk(ctx, cache, frames, warn);
    } else {
      throw InputError("captures.sequences: unknown sequence \"" + sequence +
                       "\"; allowed: autopilot, random, custom, trajectory");
    }
    for (auto& f : frames) {
      f.global_index = int(all.size());
      all.push_back(std::move(f));
    }
  }
  if (all.empty())
    throw InputError("captures.sequences: no frames to capture (autopilot needs trail.enabled = true; "
                     "random needs captures.random_count > 0)");
  check_rig_mounts(ctx, cache, all);
  return all;
}

}  // namespace silva::world
