#pragma once
/// @file Pinhole camera with OpenCV axes (x right, y down, z forward) and COLMAP pixel centres.
/// Pixel (u, v) sees the ray K^-1 (u + 0.5, v + 0.5, 1); fx = fy = W / (2 tan(fov/2)), cx = W/2, cy = H/2.
#include "core/types.hpp"

namespace silva {

/// Intrinsics, pose and clip range of one view.
struct Camera {
  int width = 0;                  ///< Image width in pixels.
  int height = 0;                 ///< Image height in pixels.
  double fx = 0, fy = 0;          ///< Focal lengths in pixels.
  double cx = 0, cy = 0;          ///< Principal point (upper-left pixel centre is (0.5, 0.5)).
  Mat4d camera_to_world = Mat4d::Identity();  ///< OpenCV camera axes -> Silva world (Z up).
  double near = 0.05;             ///< Near plane, metres along the optical axis.
  double far = 150.0;             ///< Far plane, metres along the optical axis.

  /// Camera with intrinsics from resolution and horizontal field of view (degrees).
  static Camera from_fov(int width, int height, double hfov_deg, double near, double far);
  /// World -> camera transform (inverse of camera_to_world).
  Mat4d world_to_camera() const;
  /// Camera centre in world coordinates.
  Vec3d position() const { return camera_to_world.block<3, 1>(0, 3); }
  /// World-space direction (unnormalised, camera z = 1) of the ray through pixel centre (u+0.5, v+0.5).
  Vec3d ray_direction(int u, int v) const { return world_direction(ray_x(u), ray_y(v)); }
  /// Camera-space x / z of the ray through pixel column u's centres.
  double ray_x(int u) const { return (u + 0.5 - cx) / fx; }
  /// Camera-space y / z of the ray through pixel row v's centres.
  double ray_y(int v) const { return (v + 0.5 - cy) / fy; }
  /// World-space direction of the camera-space direction (x, y, 1): ray_direction from its parts.
  Vec3d world_direction(double x, double y) const { return camera_to_world.block<3, 3>(0, 0) * Vec3d(x, y, 1.0); }
};

/// Camera-to-world rotation R = Rz(yaw) * Ry(-pitch) * Rx(roll) * B (CONTRACT.md), angles in degrees.
Mat3d rotation_from_angles(double yaw_deg, double pitch_deg, double roll_deg);

/// Inverse of rotation_from_angles: yaw, pitch, roll in degrees (pitch in [-90, 90]).
Vec3d angles_from_rotation(const Mat3d& camera_to_world_rotation);

/// Full 4x4 camera-to-world pose from a position and angles in degrees.
Mat4d pose_from_angles(const Vec3d& position, double yaw_deg, double pitch_deg, double roll_deg);

}  // namespace silva
