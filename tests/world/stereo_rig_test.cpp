#include "world/stereo_rig.hpp"

#include <gtest/gtest.h>

namespace silva::world {
namespace {

/// A left camera looking along world +Y, yawed and pitched a little, with motion while the shutter is open.
PlannedFrame left_frame() {
  PlannedFrame f;
  f.sequence = "trajectory";
  f.frame = 3;
  f.camera = Camera::from_fov(320, 240, 90, 0.05, 150);
  f.camera.camera_to_world = pose_from_angles(Vec3d(10, 20, 1.6), 75, -5, 2);
  ExposureMotion m;
  m.open_to_world = pose_from_angles(Vec3d(10, 19.99, 1.6), 75, -5, 2);
  m.close_to_world = pose_from_angles(Vec3d(10, 20.01, 1.6), 75, -5, 2);
  f.exposure_motion = m;
  return f;
}

/// Pixel column of world point `p` in `camera`, and its depth.
Eigen::Vector2d column_and_depth(const Camera& camera, const Vec3d& p) {
  const Vec3d c = camera.world_to_camera().block<3, 3>(0, 0) * p + camera.world_to_camera().block<3, 1>(0, 3);
  return {camera.fx * c.x() / c.z() + camera.cx, c.z()};
}

TEST(StereoRig, RightCameraSitsTheBaselineAlongTheLeftsX) {
  const PlannedFrame left = left_frame();
  const PlannedFrame right = stereo_right(left, 0.12);
  EXPECT_TRUE(right.right);
  EXPECT_FALSE(left.right);
  EXPECT_EQ(right.frame, left.frame);
  const Mat3d r = left.camera.camera_to_world.block<3, 3>(0, 0);
  const Mat3d right_rotation = right.camera.camera_to_world.block<3, 3>(0, 0);
  EXPECT_TRUE(right_rotation.isApprox(r));
  EXPECT_NEAR((right.camera.position() - left.camera.position() - 0.12 * r.col(0)).norm(), 0, 1e-12);
  ASSERT_TRUE(right.exposure_motion.has_value());
  EXPECT_NEAR((right.exposure_motion->open_to_world.block<3, 1>(0, 3) -
               left.exposure_motion->open_to_world.block<3, 1>(0, 3) - 0.12 * r.col(0)).norm(), 0, 1e-12);
  EXPECT_NEAR((right.exposure_motion->close_to_world.block<3, 1>(0, 3) -
               left.exposure_motion->close_to_world.block<3, 1>(0, 3) - 0.12 * r.col(0)).norm(), 0, 1e-12);
}

TEST(StereoRig, PointsShiftLeftByFocalTimesBaselineOverDepth) {
  const PlannedFrame left = left_frame(), right = stereo_right(left, 0.12);
  for (const Vec3d& p : {Vec3d(14, 21, 1.0), Vec3d(40, 30, 5.0), Vec3d(11.5, 20.2, 1.2)}) {
    const Eigen::Vector2d l = column_and_depth(left.camera, p), r = column_and_depth(right.camera, p);
    ASSERT_GT(l.y(), 0);
    EXPECT_NEAR(r.y(), l.y(), 1e-9);  // rectified: same depth in both cameras
    EXPECT_NEAR(l.x() - r.x(), left.camera.fx * 0.12 / l.y(), 1e-9);
  }
}

}  // namespace
}  // namespace silva::world
