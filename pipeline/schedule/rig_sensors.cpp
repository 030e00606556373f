#include "pipeline/schedule/rig_sensors.hpp"

#include <vector>

#include "components/sensor.hpp"
#include "systems/cast_lidar.hpp"

namespace silva::pipeline {

void mount_rig_sensors(ecs::World& world, const systems::CaptureSettings& settings, const LidarConfig& lidar) {
  std::vector<ecs::Entity> old;
  world.view<const CameraSensor>().each([&](ecs::Entity e, const CameraSensor&) { old.push_back(e); });
  world.view<const LidarSensor>().each([&](ecs::Entity e, const LidarSensor&) { old.push_back(e); });
  for (const ecs::Entity e : old) world.despawn(e);
  world.spawn(CameraSensor{false, 0.0});
  if (settings.stereo_baseline_m > 0) world.spawn(CameraSensor{true, settings.stereo_baseline_m});
  if (settings.outputs.has(io::OutputType::Lidar)) world.spawn(LidarSensor{systems::lidar_to_camera(lidar)});
}

}  // namespace silva::pipeline
