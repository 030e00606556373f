#include "core/camera_model.hpp"

namespace silva {

CameraModel camera_model(const CameraConfig& config, const Camera& camera) {
  CameraModel m;
  if (config.noise) m.noise = SensorNoise{config.full_well_e, config.read_noise_e, config.gain};
  m.vignetting = config.vignetting;
  m.chromatic_aberration = config.chromatic_aberration;
  if (config.depth_of_field)
    m.depth_of_field =
        DepthOfField{config.f_number, config.focus_distance, config.sensor_width_mm * camera.fx / double(camera.width)};
  return m;
}

}  // namespace silva
