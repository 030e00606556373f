// The trajectory sequence's walk and IMU: exact derivatives, an IMU that integrates back to the walk, the
// documented noise, and frames along the trail at the configured speed.
#include "world/trajectory.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "core/error.hpp"
#include "world/cubic_bspline.hpp"
#include "world/imu_model.hpp"
#include "world/plan_captures.hpp"
#include "world/terrain.hpp"
#include "world/world_generator.hpp"
#include "tests/common/test_library.hpp"
#include "tests/common/walk_checks.hpp"

namespace silva::world {
namespace {

/// A world of the default config (its trail is about 480 m long) for seed 11.
const WorldContext& walk_world() {
  static const WorldContext ctx = [] {
    Config cfg;
    cfg.seed = 11;
    return make_world_context(cfg, test::small_library());
  }();
  return ctx;
}

TEST(CubicBSpline, ReproducesALineWithItsExactSlope) {
  // Control value i at time (i - 1) * 0.5 is 3 + 2 i: the line 3 + 2 (t / 0.5 + 1), slope 4 per second.
  std::vector<Eigen::Vector4d> control;
  for (int i = 0; i < 8; ++i) control.push_back(Eigen::Vector4d::Constant(3.0 + 2.0 * i));
  const CubicBSpline line(control, 0.5);
  EXPECT_DOUBLE_EQ(line.end(), 2.5);
  for (double t : {0.0, 0.3, 1.0, 1.7, 2.5}) {
    const CubicBSpline::Sample s = line.at(t);
    EXPECT_NEAR(s.value[0], 3.0 + 2.0 * (t / 0.5 + 1.0), 1e-12) << t;
    EXPECT_NEAR(s.rate[2], 4.0, 1e-12) << t;
    EXPECT_NEAR(s.acceleration[3], 0.0, 1e-12) << t;
  }
}

TEST(CubicBSpline, DerivativesMatchDifferencesAcrossKnots) {
  std::vector<Eigen::Vector4d> control;
  for (int i = 0; i < 12; ++i) control.emplace_back(std::sin(i), i * i * 0.1, std::cos(3.0 * i), -i);
  const CubicBSpline curve(control, 0.25);
  const double h = 1e-6;
  for (double t = 0.01; t < curve.end() - 0.01; t += 0.0625) {  // every fourth sample on a knot
    const auto s = curve.at(t), before = curve.at(t - h), after = curve.at(t + h);
    EXPECT_LT(((after.value - before.value) / (2 * h) - s.rate).norm(), 1e-6) << t;
    EXPECT_LT(((after.rate - before.rate) / (2 * h) - s.acceleration).norm(), 1e-5) << t;
  }
}

TEST(Trajectory, VelocityAccelerationAndTurnRateAreTheDerivativesOfThePose) {
  const Trajectory walk(walk_world());
  for (double t = 0.05; t < 20.0; t += 0.731) test::expect_exact_derivatives(walk, t);
}

TEST(Trajectory, FramesWalkTheTrailAtTheConfiguredSpeedAndHeight) {
  WorldContext ctx = walk_world();
  ctx.config.trajectory.duration_s = 20;
  const std::vector<PlannedFrame> frames = plan_trajectory(ctx);
  ASSERT_EQ(frames.size(), 200u);  // 20 s at 10 Hz
  double travelled = 0;
  for (size_t i = 0; i < frames.size(); ++i) {
    const Vec3d p = frames[i].camera.position();
    EXPECT_EQ(frames[i].sequence, "trajectory");
    EXPECT_EQ(frames[i].frame, int(i));
    EXPECT_NEAR(p.z() - terrain_height(ctx.terrain, p.x(), p.y()), ctx.config.camera.ground_height, 0.15) << i;
    // Never farther from the trail's centre line than its half width.
    double nearest = INFINITY;
    for (double s = 0; s <= 40.0; s += 0.05) nearest = std::min(nearest, (ctx.trail.nav.position(s) - p).head<2>().norm());
    EXPECT_LT(nearest, 0.5 * ctx.config.trail.width) << i;
    if (i > 0) travelled += (p - frames[i - 1].camera.position()).head<2>().norm();
  }
  // 1.4 m/s for 19.9 s, the smoothed path a little shorter than the trail's bends.
  EXPECT_NEAR(travelled, 1.4 * 19.9, 0.05 * 1.4 * 19.9);
}

TEST(Trajectory, MotionBlurSpansTheWalkWhileTheShutterIsOpen) {
  WorldContext ctx = walk_world();
  ctx.config.trajectory.duration_s = 2;
  ctx.config.camera.motion_blur = true;
  ctx.config.camera.shutter_s = 0.02;
  const std::vector<PlannedFrame> frames = plan_trajectory(ctx);
  const Trajectory walk(ctx);
  for (const PlannedFrame& f : frames) {
    ASSERT_TRUE(f.exposure_motion) << f.frame;
    const double t = f.frame / 10.0;  // as plan_trajectory computes it
    EXPECT_EQ(f.exposure_motion->open_to_world, walk.at(t - 0.01).pose()) << f.frame;
    EXPECT_EQ(f.exposure_motion->close_to_world, walk.at(t + 0.01).pose()) << f.frame;
    if (f.frame == 0) continue;  // the walk starts at rest before t = 0
    const double moved = (f.exposure_motion->close_to_world - f.exposure_motion->open_to_world).block<2, 1>(0, 3).norm();
    EXPECT_NEAR(moved, 1.4 * 0.02, 0.2 * 1.4 * 0.02) << f.frame;
  }
}

TEST(Trajectory, ALidarSweepEndsWhereTheWalkIsOneRevolutionLater) {
  const WorldContext& ctx = walk_world();
  const std::vector<PlannedFrame> frames = plan_trajectory(ctx);
  const Trajectory walk(ctx);
  for (int i : {0, 7, 599})
    EXPECT_EQ(sweep_end_pose(ctx, frames[size_t(i)], 20.0), walk.at(i / 10.0 + 0.05).pose()) << i;
}

TEST(Trajectory, RunningPastTheTrailsEndIsRefusedNamingTheKeys) {
  WorldContext ctx = walk_world();
  ctx.config.trajectory.start_m = ctx.trail.nav.length() - 10.0;
  try {
    Trajectory walk(ctx);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("trajectory.duration_s"), std::string::npos) << e.what();
  }
}

/// Unit quaternion turning by the rotation vector `w * dt`.
Eigen::Quaterniond turn_by(const Vec3d& w, double dt) {
  const double angle = w.norm() * dt;
  return angle > 0 ? Eigen::Quaterniond(Eigen::AngleAxisd(angle, w.normalized())) : Eigen::Quaterniond::Identity();
}

TEST(ImuModel, NoiseFreeReadingsIntegrateBackToTheWalkWithinACentimetreOverAMinute) {
  const Trajectory walk(walk_world());
  ASSERT_DOUBLE_EQ(walk.duration(), 60.0);
  const double dt = 1.0 / 200.0;
  const RigState start = walk.at(0.0);
  Vec3d p = start.position, v = start.velocity;
  Eigen::Quaterniond q(start.rotation);
  const Vec3d gravity(0, 0, -kGravity);
  // Fourth-order Runge-Kutta on (p, v), the rotation by a fourth-order Magnus step, from the IMU's readings
  // at the steps' ends and middles: all a VIO would have, read at twice the rate.
  double worst = 0;
  for (int k = 0; k < 12000; ++k) {
    const double t = k * dt;
    const ImuSample a = ideal_imu(walk.at(t)), m = ideal_imu(walk.at(t + 0.5 * dt)), b = ideal_imu(walk.at(t + dt));
    const Eigen::Quaterniond qm = q * turn_by((a.gyro + m.gyro) * 0.5, 0.5 * dt);  // mid-step attitude
    const Eigen::Quaterniond qb = q * turn_by((a.gyro + 4.0 * m.gyro + b.gyro) / 6.0, dt);
    const Vec3d fa = q * a.accel + gravity, fm = qm * m.accel + gravity, fb = qb * b.accel + gravity;
    p += dt * v + dt * dt / 6.0 * (fa + 2.0 * fm);
    v += dt / 6.0 * (fa + 4.0 * fm + fb);
    q = qb.normalized();
    worst = std::max(worst, (p - walk.at(t + dt).position).norm());
  }
  EXPECT_LT(worst, 0.01) << "largest position error over the minute, metres";
  EXPECT_LT(Eigen::AngleAxisd(q.toRotationMatrix().transpose() * walk.at(60.0).rotation).angle(), 1e-4);
}

TEST(ImuModel, AtRestOnLevelGroundTheAccelerometerReadsGravityUpwards) {
  RigState still;
  still.rotation = rotation_from_angles(30, 0, 0);
  still.acceleration = Vec3d::Zero();
  still.angular_velocity = Vec3d::Zero();
  const ImuSample r = ideal_imu(still);
  // The camera's y axis points down: specific force +9.81 up reads -9.81 on y.
  EXPECT_NEAR(r.accel.y(), -kGravity, 1e-12);
  EXPECT_NEAR(r.accel.x(), 0, 1e-12);
  EXPECT_NEAR(r.accel.z(), 0, 1e-12);
}

TEST(ImuModel, NoiseHasTheDocumentedWhiteNoiseAndIsSeeded) {
  WorldContext ctx = walk_world();
  ctx.config.trajectory.duration_s = 30;
  const Trajectory walk(ctx);
  const ImuNoise noise = imu_noise_model("adis16448");
  const auto noisy = imu_samples(walk, 200, noise, 7), ideal = imu_samples(walk, 200, imu_noise_model("none"), 7);
  ASSERT_EQ(noisy.size(), 6000u);
  ASSERT_EQ(ideal.size(), 6000u);
  EXPECT_EQ(noisy[1].t_ns, 5'000'000);
  // First differences of the error cancel the slow bias walk: their spread is sqrt(2) x density x sqrt(rate).
  double gyro_sq = 0, accel_sq = 0;
  for (size_t k = 1; k < noisy.size(); ++k) {
    gyro_sq += ((noisy[k].gyro - ideal[k].gyro) - (noisy[k - 1].gyro - ideal[k - 1].gyro)).squaredNorm();
    accel_sq += ((noisy[k].accel - ideal[k].accel) - (noisy[k - 1].accel - ideal[k - 1].accel)).squaredNorm();
  }
  const double n = 3.0 * double(noisy.size() - 1);
  EXPECT_NEAR(std::sqrt(gyro_sq / n), std::sqrt(2.0 * 200.0) * noise.gyro_noise_density,
              0.05 * std::sqrt(2.0 * 200.0) * noise.gyro_noise_density);
  EXPECT_NEAR(std::sqrt(accel_sq / n), std::sqrt(2.0 * 200.0) * noise.accel_noise_density,
              0.05 * std::sqrt(2.0 * 200.0) * noise.accel_noise_density);
  const auto again = imu_samples(walk, 200, noise, 7), other = imu_samples(walk, 200, noise, 8);
  EXPECT_EQ(again[4321].gyro, noisy[4321].gyro);
  EXPECT_NE(other[4321].gyro, noisy[4321].gyro);
}

}  // namespace
}  // namespace silva::world
