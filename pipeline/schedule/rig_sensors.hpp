#pragma once
/// @file The capture rig's sensor entities (components/sensor.hpp), spawned from the run's settings.
#include "core/config.hpp"
#include "ecs/world.hpp"
#include "systems/render_views.hpp"

namespace silva::pipeline {

/// Replaces `world`'s sensor entities with the rig of `settings`: the left camera, the right camera when
/// settings.stereo_baseline_m > 0, and the LiDAR (mounted by `lidar`'s mount keys) when output type lidar is selected.
void mount_rig_sensors(ecs::World& world, const systems::CaptureSettings& settings, const LidarConfig& lidar);

}  // namespace silva::pipeline
