#include "core/camera.hpp"

#include <algorithm>
#include <cmath>

namespace silva {

namespace {
constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

/// Maps OpenCV camera axes to the body frame (x forward, y left, z up).
Mat3d body_from_opencv() {
  Mat3d b;
  // Columns are the images of camera x, y, z: x -> -y_body, y -> -z_body, z -> +x_body.
  b << 0, 0, 1,
      -1, 0, 0,
      0, -1, 0;
  return b;
}
}  // namespace

Camera Camera::from_fov(int width, int height, double hfov_deg, double near, double far) {
  Camera c;
  c.width = width;
  c.height = height;
  c.fx = c.fy = double(width) / (2.0 * std::tan(0.5 * hfov_deg * kDegToRad));
  c.cx = 0.5 * width;
  c.cy = 0.5 * height;
  c.near = near;
  c.far = far;
  return c;
}

Mat4d Camera::world_to_camera() const {
  Mat4d m = Mat4d::Identity();
  const Mat3d r = camera_to_world.block<3, 3>(0, 0);
  m.block<3, 3>(0, 0) = r.transpose();
  m.block<3, 1>(0, 3) = -r.transpose() * camera_to_world.block<3, 1>(0, 3);
  return m;
}

Mat3d rotation_from_angles(double yaw_deg, double pitch_deg, double roll_deg) {
  const Mat3d rz = Eigen::AngleAxisd(yaw_deg * kDegToRad, Vec3d::UnitZ()).toRotationMatrix();
  const Mat3d ry = Eigen::AngleAxisd(-pitch_deg * kDegToRad, Vec3d::UnitY()).toRotationMatrix();
  const Mat3d rx = Eigen::AngleAxisd(roll_deg * kDegToRad, Vec3d::UnitX()).toRotationMatrix();
  return rz * ry * rx * body_from_opencv();
}

Vec3d angles_from_rotation(const Mat3d& r) {
  // Body rotation M = Rz(yaw) Ry(-pitch) Rx(roll) = R * B^T.
  const Mat3d m = r * body_from_opencv().transpose();
  // For Rz(a) Ry(b) Rx(c): m(2,0) = -sin(b), m(1,0)/m(0,0) = tan(a), m(2,1)/m(2,2) = tan(c).
  const double b = std::asin(std::clamp(-m(2, 0), -1.0, 1.0));
  double a, c;
  if (std::abs(m(2, 0)) < 1.0 - 1e-12) {
    a = std::atan2(m(1, 0), m(0, 0));
    c = std::atan2(m(2, 1), m(2, 2));
  } else {  // Gimbal lock: put all of the remaining turn into yaw.
    a = std::atan2(-m(0, 1), m(1, 1));
    c = 0.0;
  }
  return Vec3d(a / kDegToRad, -b / kDegToRad, c / kDegToRad);
}

Mat4d pose_from_angles(const Vec3d& position, double yaw_deg, double pitch_deg, double roll_deg) {
  Mat4d m = Mat4d::Identity();
  m.block<3, 3>(0, 0) = rotation_from_angles(yaw_deg, pitch_deg, roll_deg);
  m.block<3, 1>(0, 3) = position;
  return m;
}

}  // namespace silva
