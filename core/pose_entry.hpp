#pragma once
/// @file One user-given camera pose (the custom sequence's pose file, parsed by io).
#include "core/types.hpp"

namespace silva {

/// One custom pose, in file order.
struct PoseEntry {
  Vec3d position = Vec3d::Zero();  ///< World position; z meaningful only when has_z.
  bool has_z = true;               ///< false: z omitted, the camera sits rig_camera_height above terrain.
  double yaw_deg = 0, pitch_deg = 0, roll_deg = 0;  ///< Given, or decomposed from the matrix.
  Mat3d rotation = Mat3d::Identity();  ///< Camera-to-world rotation: the file's matrix, or from the angles.
};

}  // namespace silva
