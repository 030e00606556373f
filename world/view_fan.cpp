#include "world/view_fan.hpp"

namespace silva::world {

std::vector<Camera> view_fan(const PlannedFrame& f) {
  if (f.fan_yaws_deg.empty()) return {f.camera};
  std::vector<Camera> views;
  views.reserve(f.fan_yaws_deg.size());
  for (const double yaw : f.fan_yaws_deg) {
    Camera c = f.camera;
    c.camera_to_world = pose_from_angles(f.camera.position(), yaw, f.pitch_deg, f.roll_deg);
    views.push_back(c);
  }
  return views;
}

}  // namespace silva::world
