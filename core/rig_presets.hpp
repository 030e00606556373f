#pragma once
/// @file The built-in sensor rigs of rig.preset (CONTRACT.md "Sensor rigs"): cameras, their height and tilt,
/// and whether the rig carries a LiDAR.
#include <span>
#include <string_view>

#include "core/config.hpp"

namespace silva {

/// One built-in rig: what it carries and where its cameras sit.
struct RigPreset {
  std::string_view name;       ///< rig.preset value
  int cameras = 1;             ///< 1: one camera; 2: a rectified stereo pair (right = left + rig.baseline_m along x)
  double height_m = 0;         ///< Camera height above the ground, metres (0: camera.ground_height)
  double pitch_deg = 0;        ///< Camera tilt from level, degrees (negative: looking down)
  bool lidar = false;          ///< The rig carries a LiDAR (output type "lidar" is added)
};

/// Every built-in rig, in the order help texts list them (the config schema's allowed rig.preset values).
std::span<const RigPreset> rig_presets();

/// The preset `rig` names (mono when the name is not a preset: the config checks refuse those).
const RigPreset& rig_preset(const RigConfig& rig);

/// The right camera's baseline, metres: rig.baseline_m for a two-camera rig, 0 for one camera.
double stereo_baseline_m(const RigConfig& rig);

/// Height of a ground capture's (left) camera above the terrain, metres: rig.height_m when set, else
/// camera.ground_height.
double rig_camera_height(const Config& config);

}  // namespace silva
