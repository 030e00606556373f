#include "world/plan_captures.hpp"

#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "world/chunk_regions.hpp"
#include "world/collision_proxy.hpp"
#include "world/terrain.hpp"

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

/// Height above the ground and pitch of autopilot/random cameras for the configured perspective.
std::pair<double, double> height_and_pitch(const Config& c) {
  return c.captures.aerial ? std::pair{c.camera.aerial_height, c.camera.aerial_pitch_deg}
                           : std::pair{c.camera.ground_height, 0.0};
}

/// Wraps an angle in degrees to (-180, 180].
double wrap_degrees(double a) {
  a = std::fmod(a, 360.0);
  if (a > 180.0) a -= 360.0;
  if (a <= -180.0) a += 360.0;
  return a;
}
}  // namespace

std::vector<PlannedFrame> plan_autopilot(const WorldContext& ctx) {
  std::vector<PlannedFrame> frames;
  if (!ctx.trail.enabled) return frames;
  const Config& c = ctx.config;
  const auto [height, pitch] = height_and_pitch(c);
  const int n = c.captures.autopilot_points;
  const double length = ctx.trail.nav.length();
  const auto& yaws = c.captures.autopilot_yaws;
  for (int i = 0; i < n; ++i) {
    const double s = n == 1 ? 0.0 : double(i) * length / double(n - 1);
    const Vec3d p = ctx.trail.nav.position(s);
    const Vec3d t = ctx.trail.nav.tangent(s);
    const double heading = std::atan2(t.y(), t.x()) * kDegPerRad;
    const double ground = terrain_height(ctx.terrain, p.x(), p.y());
    for (size_t k = 0; k < yaws.size(); ++k) {
      PlannedFrame f = make_frame(ctx, "autopilot", int(i * yaws.size() + k), Vec3d(p.x(), p.y(), ground + height),
                                  wrap_degrees(heading + yaws[k]), pitch, 0.0, c.captures.aerial);
      f.trail_s = s;
      frames.push_back(std::move(f));
    }
  }
  return frames;
}

bool pose_is_clear(const WorldContext& ctx, const std::vector<std::shared_ptr<const ChunkContent>>& chunks,
                   double x, double y, double height) {
  const Vec3f n = terrain_normal(ctx.terrain, x, y);
  if (std::acos(std::clamp(double(n.z()), -1.0, 1.0)) * kDegPerRad > kMaxWalkableSlopeDeg) return false;
  const float ground = terrain_height(ctx.terrain, x, y);
  // The camera's column: a cylinder of the clearance radius from the ground to its height.
  const float column = float(std::max(height, 0.1));
  PlacedProxy camera;
  camera.geometry = std::make_shared<fcl::Cylinderf>(float(kPoseClearance), column);
  camera.transform.translation() = fcl::Vector3f(float(x), float(y), ground + 0.5f * column);
  const double reach = kPoseClearance + ctx.max_footprint;
  for (const auto& chunk : chunks)
    for (const Vegetation& v : chunk->objects) {
      const auto& proxy = ctx.library->assets[v.asset].proxy;
      if (proxy.shape == assets::CollisionProxy::Shape::None) continue;
      if (std::hypot(v.position.x() - x, v.position.y() - y) > reach + proxy.footprint_radius() * v.scale) continue;
      if (proxies_collide(camera, place_proxy(proxy, v.position, v.yaw, v.scale))) return false;
    }
  return true;
}

std::vector<PlannedFrame> plan_random(const WorldContext& ctx, ChunkCache& cache) {
  const Config& c = ctx.config;
  const auto [height, pitch] = height_and_pitch(c);
  const double half = 0.5 * c.world.extent;
  const double reach = kPoseClearance + ctx.max_footprint;
  std::vector<PlannedFrame> frames;
  for (int f = 0; f < c.captures.random_count; ++f) {
    Rng rng(uint64_t(c.seed), uint64_t(f), Purpose::RandomPose);
    bool found = false;
    for (int attempt = 0; attempt < kMaxPoseAttempts && !found; ++attempt) {
      const double x = rng.range(float(-half), float(half));
      const double y = rng.range(float(-half), float(half));
      const double yaw = rng.range(-180.0f, 180.0f);
      const auto chunks = cache.require(ctx, chunks_in_disc(x, y, reach, ctx.chunk_size()));
      if (!pose_is_clear(ctx, chunks, x, y, height)) continue;
      const double ground = terrain_height(ctx.terrain, x, y);
      frames.push_back(make_frame(ctx, "random", f, Vec3d(x, y, ground + height), yaw, pitch, 0.0, c.captures.aerial));
      found = true;
    }
    if (!found)
      throw InputError("captures.random_count: found no walkable pose clear of obstacles for random frame " +
                       std::to_string(f) + " in " + std::to_string(kMaxPoseAttempts) +
                       " tries; lower vegetation.density or enlarge world.extent");
  }
  return frames;
}

std::vector<PlannedFrame> plan_custom(const WorldContext& ctx, const std::vector<PoseEntry>& poses) {
  std::vector<PlannedFrame> frames;
  for (size_t i = 0; i < poses.size(); ++i) {
    const PoseEntry& p = poses[i];
    Vec3d position = p.position;
    if (!p.has_z) position.z() = terrain_height(ctx.terrain, p.position.x(), p.position.y()) + ctx.config.camera.ground_height;
    PlannedFrame f = make_frame(ctx, "custom", int(i), position, p.yaw_deg, p.pitch_deg, p.roll_deg, false);
    f.camera.camera_to_world.block<3, 3>(0, 0) = p.rotation;  // exact matrix when the file gave one
    frames.push_back(std::move(f));
  }
  return frames;
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
    } else if (sequence == "random") {
      frames = plan_random(ctx, cache);
    } else if (sequence == "custom") {
      frames = plan_custom(ctx, custom_poses);
    } else {
      throw InputError("captures.sequences: unknown sequence \"" + sequence + "\"; allowed: autopilot, random, custom");
    }
    for (auto& f : frames) {
      f.global_index = int(all.size());
      all.push_back(std::move(f));
    }
  }
  if (all.empty())
    throw InputError("captures.sequences: no frames to capture (autopilot needs trail.enabled = true; "
                     "random needs captures.random_count > 0)");
  return all;
}

}  // namespace silva::world
