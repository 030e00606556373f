// Known answers for the LiDAR model: a 16-beam sensor above a plane, beside a box and an alpha card.
#include "raycast/lidar.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <map>

#include <Eigen/Geometry>

#include "tests/raycast/test_meshes.hpp"

namespace silva::raycast {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

/// 16 beams from -15 to +15 degrees every 2, one column per degree, no noise.
LidarPreset sixteen_beams() {
  LidarPreset p;
  p.name = "test16";
  for (int r = 0; r < 16; ++r) p.elevations_deg.push_back(-15.0 + 2.0 * r);
  p.columns = 360;
  p.rotation_hz = 10;
  p.min_range = 0.5;
  p.max_range = 100;
  p.range_noise_m = 0;
  p.dropout = 0;
  p.intensity_noise = 0;
  return p;
}

/// The known-answer scene: a plane at z = 0, a 2 m box centred at (-5, 0, 2) (behind the sensor)
/// and a 2 m alpha card facing -y at y = 3, centred at (-0.5, 3, 2), opaque where x > -0.5.
struct Fixture {
  Mesh plane = test::square(400.0f), cube = test::box(1.0f), card = test::alpha_card(2.0f);
  RayScene scene;
  Fixture() {
    Affine3f card_pose = test::placed({-0.5f, 3.0f, 2.0f});
    card_pose.block<3, 3>(0, 0) << 0, -1, 0, 1, 0, 0, 0, 0, 1;  // the card's +y (u) turns to -x
    const RayInstance instances[] = {{&plane, test::placed({0, 0, 0}), 0},
                                     {&cube, test::placed({-5, 0, 2}), 77},
                                     {&card, card_pose, 0}};
    scene.add_group(0, instances);
    scene.commit();
  }
};

/// Sensor at (0, 0, 2), axes aligned with the world.
SweepPose at_two_metres() {
  SweepPose pose;
  pose.position = Vec3d(0, 0, 2);
  pose.seed = 5;
  pose.key = 9;
  return pose;
}

TEST(Lidar, SixteenBeamsGiveTheAnalyticPointsRingsAndRanges) {
  Fixture f;
  const LidarPreset preset = sixteen_beams();
  const std::vector<LidarPoint> points = cast_sweep(f.scene, preset, at_two_metres(), {});
  std::map<std::pair<int, int>, LidarPoint> by_ray;
  for (const LidarPoint& p : points) by_ray[{p.column, p.ring}] = p;
  EXPECT_EQ(by_ray.size(), points.size());
  auto expect_point = [&](int column, int ring, double range, Role role, uint32_t instance) {
    const auto it = by_ray.find({column, ring});
    ASSERT_NE(it, by_ray.end()) << "column " << column << " ring " << ring;
    const LidarPoint& p = it->second;
    EXPECT_NEAR(p.range, range, 1e-4) << "column " << column << " ring " << ring;
    const Vec3d d = beam_direction(preset, ring, column);
    EXPECT_NEAR((p.position.cast<double>() - range * d).norm(), 0.0, 1e-4);
    EXPECT_EQ(p.role, role) << "column " << column << " ring " << ring;
    EXPECT_EQ(p.instance_id, instance);
    EXPECT_FLOAT_EQ(p.time, float(column / 3600.0));
  };
  // The plane: beams below the horizon at 2 / sin(-elevation) where nothing is in the way; -1 degree
  // would land at 114.6 m, beyond max_range; beams at or above the horizon return nothing.
  for (int ring = 0; ring < 16; ++ring) {
    const double e = preset.elevations_deg[size_t(ring)];
    const double range = 2.0 / std::sin(-e * kDeg);
    if (e < 0 && range <= preset.max_range)
      expect_point(200, ring, range, Role::Ground, 0);
    else
      EXPECT_EQ(by_ray.count({200, ring}), 0u) << "ring " << ring;
  }
  // Column 0 looks backwards (-x) at the box face x = -4: beams within atan(1/4) of the horizon.
  for (int ring = 1; ring < 15; ++ring)
    expect_point(0, ring, 4.0 / std::cos(preset.elevations_deg[size_t(ring)] * kDeg), Role::Obstacle, 77);
  expect_point(0, 0, 2.0 / std::sin(15 * kDeg), Role::Ground, 0);  // passes under the box
  EXPECT_EQ(by_ray.count({0, 15}), 0u);                             // passes over it
  // Column 90 looks left (+y) at the card's opaque half: every beam at 3 / cos(elevation).
  for (int ring = 0; ring < 16; ++ring)
    expect_point(90, ring, 3.0 / std::cos(preset.elevations_deg[size_t(ring)] * kDeg), Role::TreeCanopy, 0);
  // Column 80 crosses the card where its mask is transparent (x = -0.53): ground or nothing.
  expect_point(80, 0, 2.0 / std::sin(15 * kDeg), Role::Ground, 0);
  EXPECT_EQ(by_ray.count({80, 10}), 0u);
  // Points come in firing order.
  for (size_t i = 1; i < points.size(); ++i)
    EXPECT_LT(std::make_pair(points[i - 1].column, points[i - 1].ring), std::make_pair(points[i].column, points[i].ring));
}

TEST(Lidar, IntensityFollowsIncidenceAndRange) {
  Fixture f;
  LidarPreset preset = sixteen_beams();
  preset.intensity_falloff = 0.01;
  const std::vector<LidarPoint> points = cast_sweep(f.scene, preset, at_two_metres(), {});
  for (const LidarPoint& p : points) {
    if (p.column != 200 || p.ring > 6) continue;
    const double e = -preset.elevations_deg[p.ring] * kDeg;  // incidence on the plane: sin(e)
    EXPECT_NEAR(p.intensity, nir_reflectivity(Material::Ground) * std::sin(e) * std::exp(-0.01 * p.range), 1e-5);
  }
}

TEST(Lidar, NoiseAndDropoutAreSeededAndTheSameForAnyThreadCount) {
  Fixture f;
  LidarPreset preset = sixteen_beams();
  preset.range_noise_m = 0.05;
  preset.dropout = 0.2;
  preset.intensity_noise = 0.02;
  auto sweep = [&](int threads, uint64_t key) {
    std::vector<LidarPoint> out;
    SweepPose pose = at_two_metres();
    pose.key = key;
    tbb::task_arena(threads).execute([&] { out = cast_sweep(f.scene, preset, pose, {}); });
    return out;
  };
  const std::vector<LidarPoint> one = sweep(1, 9), two = sweep(2, 9), other = sweep(2, 10);
  ASSERT_EQ(one.size(), two.size());
  for (size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].position, two[i].position);
    EXPECT_EQ(one[i].intensity, two[i].intensity);
  }
  EXPECT_NE(one.size(), other.size());
  // Dropout 0.2 keeps about 80 % of the noiseless returns; the range error has the preset's sigma.
  const size_t clean = cast_sweep(f.scene, sixteen_beams(), at_two_metres(), {}).size();
  EXPECT_NEAR(double(one.size()) / double(clean), 0.8, 0.02);
  double sum2 = 0;
  int n = 0;
  for (const LidarPoint& p : one) {
    if (p.role != Role::Ground || p.column < 100 || p.column > 300) continue;
    const double truth = 2.0 / std::sin(-preset.elevations_deg[p.ring] * kDeg);
    sum2 += (p.range - truth) * (p.range - truth);
    ++n;
  }
  ASSERT_GT(n, 500);
  EXPECT_NEAR(std::sqrt(sum2 / n), 0.05, 0.005);
}

TEST(Lidar, MotionDistortionShiftsEachPointBySpeedTimesItsTime) {
  // A wall facing the sensor at x = 10; the sensor at (0, 0, 2) moves along +x at 5 m/s during a 10 Hz sweep.
  Mesh wall = test::square(400.0f, Role::Obstacle);
  Affine3f wall_pose = test::placed({10.0f, 0.0f, 0.0f});
  wall_pose.block<3, 3>(0, 0) << 0, 0, -1, 0, 1, 0, 1, 0, 0;  // the square's +z (its front) turns to -x
  RayScene scene;
  const RayInstance instances[] = {{&wall, wall_pose, 5}};
  scene.add_group(0, instances);
  scene.commit();
  const LidarPreset preset = sixteen_beams();
  const double speed = 5.0;
  SweepPose still = at_two_metres();
  SweepPose moving = still;
  moving.end = SweepEnd{Mat3d::Identity(), still.position + Vec3d(speed / preset.rotation_hz, 0, 0)};
  const std::vector<LidarPoint> fixed = cast_sweep(scene, preset, still, {});
  const std::vector<LidarPoint> moved = cast_sweep(scene, preset, moving, {});
  ASSERT_GT(moved.size(), 1000u);
  ASSERT_EQ(moved.size(), fixed.size());
  for (size_t i = 0; i < moved.size(); ++i) {
    const LidarPoint& p = moved[i];
    ASSERT_EQ(p.role, Role::Obstacle);
    // Still: every wall point at x = 10. Moving: fired from x = v t, so 10 - v t ahead in the firing frame.
    EXPECT_NEAR(fixed[i].position.x(), 10.0, 1e-4);
    EXPECT_NEAR(p.position.x(), 10.0 - speed * double(p.time), 1e-4) << "column " << p.column;
    // The beam's direction is the sensor's own: y and z scale with the shorter range.
    EXPECT_NEAR(p.position.y() / p.position.x(), fixed[i].position.y() / fixed[i].position.x(), 1e-5);
    EXPECT_NEAR(p.position.z() / p.position.x(), fixed[i].position.z() / fixed[i].position.x(), 1e-5);
  }
  // A turning sensor: a yaw of 36 degrees over the sweep turns column c's beam by 36 c / columns degrees.
  SweepPose turning = still;
  turning.end = SweepEnd{Eigen::AngleAxisd(36 * kDeg, Vec3d::UnitZ()).toRotationMatrix(), still.position};
  for (const LidarPoint& p : cast_sweep(scene, preset, turning, {})) {
    const double yaw = 36 * kDeg * p.column / preset.columns;
    const Vec3d world = Eigen::AngleAxisd(yaw, Vec3d::UnitZ()) * p.position.cast<double>();
    EXPECT_NEAR(world.x(), 10.0, 1e-4) << "column " << p.column;  // every point still lies on the wall
  }
}

}  // namespace
}  // namespace silva::raycast
