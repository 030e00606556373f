#include "core/rig_presets.hpp"

#include <array>

namespace silva {

namespace {

/// Ground robot: a stereo camera 0.55 m up on a small wheeled base (Clearpath Jackal-sized) with a LiDAR above it.
/// Drone: one camera 3 m above the trail, tilted 15 degrees down, as trail-following quadrotors fly.
constexpr std::array kPresets = {
    RigPreset{"mono", 1, 0.0, 0.0, false, "one camera at camera.ground_height"},
    RigPreset{"stereo", 2, 0.0, 0.0, false, "a rectified stereo pair at camera.ground_height"},
    RigPreset{"ground_robot", 2, 0.55, 0.0, true, "a stereo pair 0.55 m above the ground with a LiDAR 0.3 m above it"},
    RigPreset{"drone", 1, 3.0, -15.0, false, "one camera 3 m above the ground, tilted 15 degrees down"},
};

}  // namespace

std::span<const RigPreset> rig_presets() { return kPresets; }

const RigPreset* find_rig_preset(std::string_view name) {
  for (const RigPreset& p : kPresets)
    if (p.name == name) return &p;
  return nullptr;
}

std::string rig_preset_names() {
  std::string out;
  for (const RigPreset& p : kPresets) out += (out.empty() ? "" : ", ") + std::string(p.name);
  return out;
}

const RigPreset& rig_preset(const RigConfig& rig) {
  const RigPreset* p = find_rig_preset(rig.preset);
  return p ? *p : kPresets.front();
}

double stereo_baseline_m(const RigConfig& rig) { return rig.cameras == 2 ? rig.baseline_m : 0.0; }

double rig_camera_height(const Config& config) {
  return config.rig.height_m > 0 ? config.rig.height_m : config.camera.ground_height;
}

}  // namespace silva
