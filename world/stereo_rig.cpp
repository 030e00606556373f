#include "world/stereo_rig.hpp"

namespace silva::world {

namespace {

/// `pose` moved `distance` metres along its own camera +x axis.
Mat4d along_camera_x(const Mat4d& pose, double distance) {
  Mat4d moved = pose;
  moved.block<3, 1>(0, 3) += distance * pose.block<3, 1>(0, 0);
  return moved;
}

}  // namespace

PlannedFrame stereo_right(const PlannedFrame& left, double baseline_m) {
  PlannedFrame right = left;
  right.right = true;
  right.camera.camera_to_world = along_camera_x(left.camera.camera_to_world, baseline_m);
  if (right.exposure_motion) {
    right.exposure_motion->open_to_world = along_camera_x(left.exposure_motion->open_to_world, baseline_m);
    right.exposure_motion->close_to_world = along_camera_x(left.exposure_motion->close_to_world, baseline_m);
  }
  return right;
}

}  // namespace silva::world
