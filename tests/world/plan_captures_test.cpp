#include "world/plan_captures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "world/chunk_regions.hpp"
#include "world/terrain.hpp"
#include "world/world_generator.hpp"
#include "tests/common/test_library.hpp"

namespace silva::world {
namespace {

using Shape = assets::CollisionProxy::Shape;

/// Signed distance from world point `p` to the solid proxy of `v` (negative inside), computed
/// analytically in the object's frame (independent of FCL).
double proxy_distance(const assets::CollisionProxy& proxy, const Vegetation& v, const Vec3d& p) {
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(v.yaw, Vec3d::UnitZ()).toRotationMatrix();
  const Vec3d local = turn.transpose() * (p - v.position.cast<double>()) / double(v.scale);
  const Vec3d q = local - proxy.center.cast<double>();
  const Vec3d axis = proxy.axis.cast<double>().normalized();
  double d = 0;
  switch (proxy.shape) {
    case Shape::Sphere:
      d = q.norm() - proxy.radius;
      break;
    case Shape::Capsule: {
      const double t = std::clamp(q.dot(axis), -0.5 * proxy.height, 0.5 * proxy.height);
      d = (q - t * axis).norm() - proxy.radius;
      break;
    }
    case Shape::Cylinder: {
      const double along = q.dot(axis);
      const double radial = (q - along * axis).norm() - proxy.radius;
      const double axial = std::abs(along) - 0.5 * proxy.height;
      d = std::min(std::max(radial, axial), 0.0) + std::hypot(std::max(radial, 0.0), std::max(axial, 0.0));
      break;
    }
    case Shape::Box: {
      const Vec3d e = q.cwiseAbs() - proxy.half_extents.cast<double>();
      d = std::min(e.maxCoeff(), 0.0) + e.cwiseMax(0.0).norm();
      break;
    }
    case Shape::None:
      return INFINITY;
  }
  return d * v.scale;
}

std::vector<PlannedFrame> frames_of(const std::vector<PlannedFrame>& plan, const std::string& sequence) {
  std::vector<PlannedFrame> out;
  for (const auto& f : plan)
    if (f.sequence == sequence) out.push_back(f);
  return out;
}

TEST(PlanCaptures, DefaultSettingsPlan690AutopilotAnd100Random) {
  Config cfg;  // the thesis defaults
  cfg.seed = 20240501;
  const WorldContext ctx = make_world_context(cfg, test::small_library());
  ChunkCache cache(256);
  std::vector<std::string> warnings;
  const auto plan = plan_captures(ctx, cache, {}, [&](const std::string& w) { warnings.push_back(w); });
  EXPECT_TRUE(warnings.empty());
  ASSERT_EQ(plan.size(), 790u);
  const auto autopilot = frames_of(plan, "autopilot");
  const auto random = frames_of(plan, "random");
  ASSERT_EQ(autopilot.size(), 690u);  // 230 points x 3 yaws
  ASSERT_EQ(random.size(), 100u);
  for (size_t k = 0; k < plan.size(); ++k) {
    EXPECT_EQ(plan[k].global_index, int(k));
    EXPECT_EQ(plan[k].frame, int(k < 690 ? k : k - 690));  // autopilot first (config order), then random
    EXPECT_EQ(plan[k].camera.width, 1920);
    EXPECT_EQ(plan[k].camera.height, 1080);
    EXPECT_FALSE(plan[k].aerial);
  }
  // Thesis intrinsics: 90° horizontal fov at 1920x1080.
  EXPECT_NEAR(plan[0].camera.fx, 960.0, 1e-9);
  EXPECT_NEAR(plan[0].camera.cy, 540.0, 1e-9);
  // Autopilot: both ends of the spline, yaws -45/0/+45 around the tangent at each point.
  EXPECT_DOUBLE_EQ(*autopilot.front().trail_s, 0.0);
  EXPECT_NEAR(*autopilot.back().trail_s, ctx.trail.nav.length(), 1e-9);
  for (size_t i = 0; i < 230; ++i) {
    const auto& left = autopilot[3 * i];
    const auto& ahead = autopilot[3 * i + 1];
    const auto& right = autopilot[3 * i + 2];
    EXPECT_EQ(*left.trail_s, *ahead.trail_s);
    EXPECT_EQ(*right.trail_s, *ahead.trail_s);
    EXPECT_NEAR(std::remainder(ahead.yaw_deg - left.yaw_deg, 360.0), 45.0, 1e-9);
    EXPECT_NEAR(std::remainder(right.yaw_deg - ahead.yaw_deg, 360.0), 45.0, 1e-9);
    if (i > 0) {
      EXPECT_GT(*ahead.trail_s, *autopilot[3 * i - 2].trail_s);
    }
  }
  for (const auto& f : random) EXPECT_FALSE(f.trail_s.has_value());
}

TEST(PlanCaptures, TrailOffSkipsAutopilotWithAWarning) {
  Config cfg = test::small_world_config(5);
  cfg.trail.enabled = false;
  cfg.captures.random_count = 3;
  const WorldContext ctx = make_world_context(cfg, test::small_library());
  ChunkCache cache(64);
  std::vector<std::string> warnings;
  const auto plan = plan_captures(ctx, cache, {}, [&](const std::string& w) { warnings.push_back(w); });
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("trail.enabled"), std::string::npos);
  ASSERT_EQ(plan.size(), 3u);
  EXPECT_EQ(plan[0].sequence, "random");

  cfg.captures.sequences = {"autopilot"};
  const WorldContext only_autopilot = make_world_context(cfg, test::small_library());
  EXPECT_THROW(plan_captures(only_autopilot, cache, {}, [](const std::string&) {}), InputError);
}

// Random poses: inside the capture region, camera_height above the terrain, on walkable
// slopes, and at least captures.clearance from every solid proxy of the placed world (checked
// against freshly generated chunks, with analytic distances), for several seeds and a dense forest.
TEST(PlanCaptures, RandomPosesClearOfEveryProxyAndAboveTheTerrain) {
  for (int64_t seed : {1, 7, 99, 123456}) {
    Config cfg = test::small_world_config(seed, 25);
    cfg.captures.random_count = 40;
    const WorldContext ctx = make_world_context(cfg, test::small_library());
    ChunkCache cache(64);
    const auto frames = plan_random(ctx, cache);
    ASSERT_EQ(frames.size(), 40u);
    int near_misses = 0;
    for (const auto& f : frames) {
      if (f.pose_fix == PoseFix::Unresolvable) continue;  // counted in run.json, kept where drawn
      const Vec3d p = f.camera.position();
      SCOPED_TRACE("seed " + std::to_string(seed) + " frame " + std::to_string(f.frame));
      EXPECT_LE(std::abs(p.x()), 0.5 * cfg.world.extent);
      EXPECT_LE(std::abs(p.y()), 0.5 * cfg.world.extent);
      const double ground = terrain_height(ctx.terrain, p.x(), p.y());
      EXPECT_NEAR(p.z() - ground, cfg.camera.ground_height, 1e-4);
      const Vec3f n = terrain_normal(ctx.terrain, p.x(), p.y());
      EXPECT_GE(n.z(), std::cos(kMaxWalkableSlopeDeg * M_PI / 180.0) - 1e-6);
      EXPECT_EQ(f.pitch_deg, 0.0);
      EXPECT_GE(f.yaw_deg, -180.0);
      EXPECT_LE(f.yaw_deg, 180.0);
      double nearest = INFINITY;
      for (ChunkCoord c : chunks_in_disc(p.x(), p.y(), 15.0, ctx.chunk_size())) {
        const ChunkContent chunk = generate_chunk(ctx, c);
        for (const Vegetation& v : chunk.objects) {
          const auto& proxy = ctx.library->assets[v.asset].proxy;
          // The camera and the column below it, down to 0.5 m above the ground.
          for (double h : {0.5, 1.0, cfg.camera.ground_height})
            nearest = std::min(nearest, proxy_distance(proxy, v, Vec3d(p.x(), p.y(), ground + h)));
        }
      }
      EXPECT_GE(nearest, cfg.captures.clearance - 1e-3);
      near_misses += nearest < 2.5;
    }
    EXPECT_GT(near_misses, 0) << "a dense forest should bring some poses close to an obstacle";
  }
}

TEST(PlanCaptures, RandomPosesDependOnlyOnSeedAndFrame) {
  Config cfg = test::small_world_config(31, 10);
  cfg.captures.random_count = 6;
  ChunkCache cache_a(64), cache_b(4);
  const auto a = plan_random(make_world_context(cfg, test::small_library()), cache_a);
  cfg.captures.random_count = 3;
  const auto b = plan_random(make_world_context(cfg, test::small_library()), cache_b);
  ASSERT_EQ(b.size(), 3u);
  for (size_t k = 0; k < b.size(); ++k) {
    EXPECT_EQ(a[k].camera.camera_to_world, b[k].camera.camera_to_world);
    EXPECT_EQ(a[k].yaw_deg, b[k].yaw_deg);
  }
  cfg.seed = 32;
  const auto c = plan_random(make_world_context(cfg, test::small_library()), cache_b);
  EXPECT_NE(a[0].camera.camera_to_world, c[0].camera.camera_to_world);
}

TEST(PlanCaptures, CustomPosesKeepFileOrderAndDropToTheGroundWithoutZ) {
  const Config cfg = test::small_world_config(3);
  const WorldContext ctx = make_world_context(cfg, test::small_library());
  PoseEntry with_z;
  with_z.position = Vec3d(1, 2, 30);
  with_z.yaw_deg = 10;
  with_z.rotation = rotation_from_angles(10, 0, 0);
  PoseEntry without_z;
  without_z.position = Vec3d(-5, 4, 0);
  without_z.has_z = false;
  const auto frames = plan_custom(ctx, {with_z, without_z});
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].frame, 0);
  EXPECT_EQ(frames[1].frame, 1);
  EXPECT_EQ(frames[0].camera.position(), Vec3d(1, 2, 30));
  EXPECT_NEAR(frames[1].camera.position().z(), terrain_height(ctx.terrain, -5, 4) + cfg.camera.ground_height, 1e-6);
  EXPECT_EQ(frames[0].yaw_deg, 10);
}

}  // namespace
}  // namespace silva::world

namespace silva::world {
namespace {

TEST(PlanCaptures, AutopilotMotionSpansSpeedTimesShutterAlongTheTrail) {
  Config cfg = test::small_world_config(77);
  cfg.captures.autopilot_points = 5;
  cfg.camera.autopilot_speed = 2.0;
  cfg.camera.shutter_s = 0.05;  // 0.1 m of trail while the shutter is open
  const WorldContext ctx = make_world_context(cfg, test::small_library());
  std::vector<PlannedFrame> frames = plan_autopilot(ctx);
  for (const PlannedFrame& f : frames) EXPECT_FALSE(f.exposure_motion.has_value());
  add_autopilot_motion(ctx, frames);
  const double length = ctx.trail.nav.length();
  for (const PlannedFrame& f : frames) {
    ASSERT_TRUE(f.exposure_motion.has_value());
    const ExposureMotion& m = *f.exposure_motion;
    EXPECT_EQ(m.shutter_s, 0.05);
    const Vec3d open = m.open_to_world.block<3, 1>(0, 3), close = m.close_to_world.block<3, 1>(0, 3);
    const double s = *f.trail_s;
    const double span = std::min(s + 0.05, length) - std::max(s - 0.05, 0.0);  // kept within the trail
    EXPECT_NEAR((close - open).norm(), span, 0.01 * span) << f.frame;
    if (s > 0.05 && s < length - 0.05) {  // the frame's pose is the middle of the exposure
      EXPECT_NEAR((0.5 * (open + close) - f.camera.position()).norm(), 0.0, 2e-3) << f.frame;
    }
    // The camera looks the same way relative to the trail: its forward axis barely turns.
    const Vec3d forward = f.camera.camera_to_world.block<3, 1>(0, 2);
    EXPECT_GT(forward.dot(m.open_to_world.block<3, 1>(0, 2)), 0.999);
    EXPECT_GT(forward.dot(m.close_to_world.block<3, 1>(0, 2)), 0.999);
  }
}

}  // namespace
}  // namespace silva::world
