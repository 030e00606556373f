#pragma once
/// @file One pose of a user's timed camera trajectory (config trajectory.file, TUM form).
#include "core/types.hpp"

namespace silva {

/// A camera pose at a time: where the trajectory sequence's camera is at `t`.
struct TimedPose {
  double t = 0;                     ///< Seconds (the file's clock; the walk starts at the first pose).
  Vec3d position = Vec3d::Zero();   ///< Camera centre, world metres.
  Mat3d rotation = Mat3d::Identity();  ///< camera_to_world rotation (OpenCV camera axes → Silva world).
};

}  // namespace silva
