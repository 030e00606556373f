#include "core/camera.hpp"

#include <gtest/gtest.h>

namespace silva {

TEST(Camera, IntrinsicsFollowContract) {
  const Camera c = Camera::from_fov(1920, 1080, 90.0, 0.05, 150.0);
  EXPECT_NEAR(c.fx, 960.0, 1e-9);
  EXPECT_NEAR(c.fy, 960.0, 1e-9);
  EXPECT_DOUBLE_EQ(c.cx, 960.0);
  EXPECT_DOUBLE_EQ(c.cy, 540.0);
}

TEST(Camera, ZeroAnglesLookAlongPlusXWithRightTowardsMinusY) {
  const Mat3d r = rotation_from_angles(0, 0, 0);
  EXPECT_TRUE(r.col(2).isApprox(Vec3d(1, 0, 0)));   // camera z (forward) -> world +X
  EXPECT_TRUE(r.col(0).isApprox(Vec3d(0, -1, 0)));  // camera x (right) -> world -Y
  EXPECT_TRUE(r.col(1).isApprox(Vec3d(0, 0, -1)));  // camera y (down) -> world -Z
}

TEST(Camera, YawTurnsLeftAndPitchLooksUp) {
  EXPECT_TRUE(rotation_from_angles(90, 0, 0).col(2).isApprox(Vec3d(0, 1, 0), 1e-12));
  const Vec3d f = rotation_from_angles(0, 30, 0).col(2);
  EXPECT_GT(f.z(), 0.49);
}

TEST(Camera, AnglesRoundTrip) {
  for (double yaw : {-170.0, -45.0, 0.0, 33.0, 120.0})
    for (double pitch : {-80.0, -45.0, 0.0, 20.0})
      for (double roll : {-30.0, 0.0, 10.0}) {
        const Vec3d a = angles_from_rotation(rotation_from_angles(yaw, pitch, roll));
        EXPECT_NEAR(a.x(), yaw, 1e-9);
        EXPECT_NEAR(a.y(), pitch, 1e-9);
        EXPECT_NEAR(a.z(), roll, 1e-9);
      }
}

TEST(Camera, CentreRayIsOpticalAxis) {
  Camera c = Camera::from_fov(4, 4, 90.0, 0.05, 150.0);
  c.camera_to_world = pose_from_angles(Vec3d(1, 2, 3), 0, 0, 0);
  // Pixel (2,2) has centre (2.5, 2.5): half a pixel right and down of the principal point (2,2).
  const Vec3d d = c.ray_direction(2, 2);
  EXPECT_NEAR(d.x(), 1.0, 1e-12);
  EXPECT_NEAR(d.y(), -0.25, 1e-12);
  EXPECT_NEAR(d.z(), -0.25, 1e-12);
}

}  // namespace silva
