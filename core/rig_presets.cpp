#include "core/rig_presets.hpp"

#include <array>

namespace silva {

namespace {

/// Ground robot: a stereo camera 0.55 m up on a small wheeled base (Clearpath Jackal-sized) with a LiDAR above it.
/// Drone: one camera 3 m above the trail, tilted 15 degrees down, as trail-following quadrotors fly.
constexpr std::array kPresets = {
    RigPreset{"mono", 1, 0.0, 0.0, false},
    RigPreset{"stereo", 2, 0.0, 0.0, false},
    RigPreset{"ground_robot", 2, 0.55, 0.0, true},
    RigPreset{"drone", 1, 3.0, -15.0, false},
};

}  // namespace

std::span<const RigPreset> rig_presets() { return kPresets; }

const RigPreset& rig_preset(const RigConfig& rig) {
  for (const RigPreset& p : kPresets)
    if (p.name == rig.preset) return p;
  return kPresets.front();
}

double stereo_baseline_m(const RigConfig& rig) { return rig.cameras == 2 ? rig.baseline_m : 0.0; }

double rig_camera_height(const Config& config) {
  return config.rig.height_m > 0 ? config.rig.height_m : config.camera.ground_height;
}

}  // namespace silva
