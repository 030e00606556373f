#pragma once
/// @file Sensor entities of the capture rig (CONTRACT.md "Sensor rigs"): one entity per camera and one for the
/// LiDAR, each with its mount on the rig's left camera; render_views and cast_lidar query them.
#include "core/types.hpp"

namespace silva {

/// A camera of the rig: the left camera (the planned frame's own) or the right camera of a stereo pair.
struct CameraSensor {
  bool right = false;     ///< The stereo pair's right camera (outputs in <type>_right/)
  double baseline_m = 0;  ///< Its mount: metres along the left camera's +x (0 for the left camera)
};

/// The rig's LiDAR and its mount on the left camera.
struct LidarSensor {
  Mat4d sensor_to_camera = Mat4d::Identity();  ///< LiDAR frame -> left camera frame (lidar.mount_offset/_rpy_deg)
};

}  // namespace silva
