// A walk through a user's timed poses (trajectory.file): it follows the poses, its derivatives are exact (pitch
// and roll turning too), and its length is the file's span.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "core/camera.hpp"
#include "world/trajectory.hpp"
#include "world/world_generator.hpp"
#include "tests/common/test_library.hpp"
#include "tests/common/walk_checks.hpp"

namespace silva::world {
namespace {

/// A world of the default config for seed 11, its trail walk without bob and sway.
WorldContext still_walk_world() {
  Config cfg;
  cfg.seed = 11;
  cfg.trajectory.bob_m = 0;
  cfg.trajectory.sway_deg = 0;
  return make_world_context(cfg, test::small_library());
}

/// Poses every `dt` seconds from `t0` over `span` seconds of `walk`, pitched and rolled by slow waves when `wave`.
std::vector<TimedPose> sampled_poses(const Trajectory& walk, double t0, double dt, double span, bool wave) {
  std::vector<TimedPose> poses;
  for (int i = 0; i * dt <= span + 1e-9; ++i) {
    const double t = i * dt;
    const RigState s = walk.at(t);
    const double pitch = wave ? 10.0 * std::sin(0.4 * t) : s.pitch_deg, roll = wave ? 5.0 * std::cos(0.3 * t) : s.roll_deg;
    poses.push_back({t0 + t, s.position, rotation_from_angles(s.yaw_deg, pitch, roll)});
  }
  return poses;
}

double angle_between(const Mat3d& a, const Mat3d& b) { return Eigen::AngleAxisd(a.transpose() * b).angle(); }

TEST(TrajectoryFile, WalksThroughTheFilesPoses) {
  const WorldContext trail_world = still_walk_world();
  const Trajectory trail(trail_world);
  WorldContext file_world = still_walk_world();
  file_world.walk_poses = sampled_poses(trail, 1000.0, 0.1, 20.0, false);  // the file's clock starts at 1000 s
  const Trajectory walk(file_world);
  EXPECT_NEAR(walk.duration(), 20.0, 1e-9);
  for (double t = 0; t <= 20.0; t += 0.05) {
    const RigState a = trail.at(t), b = walk.at(t);
    EXPECT_LT((a.position - b.position).norm(), 0.002) << t;
    EXPECT_LT(angle_between(a.rotation, b.rotation), 0.1 * M_PI / 180) << t;
    EXPECT_FALSE(b.trail_s.has_value());
  }
}

TEST(TrajectoryFile, TurnRateIsTheDerivativeOfTheRotationWithPitchAndRollTurning) {
  const WorldContext trail_world = still_walk_world();
  WorldContext file_world = still_walk_world();
  file_world.walk_poses = sampled_poses(Trajectory(trail_world), 0.0, 0.05, 15.0, true);
  const Trajectory walk(file_world);
  for (double t = 0.05; t < 15.0; t += 0.613) {
    test::expect_exact_derivatives(walk, t);
    EXPECT_NEAR(walk.at(t).pitch_deg, 10.0 * std::sin(0.4 * t), 0.2) << t;  // the wave survives the smoothing
  }
}

}  // namespace
}  // namespace silva::world
