#include "core/camera_model.hpp"

#include <algorithm>
#include <cmath>

namespace silva {

CameraModel camera_model(const CameraConfig& config, const Camera& camera) {
  CameraModel m;
  if (config.noise)
    m.noise = SensorNoise{config.full_well_e, config.read_noise_e, config.gain, std::max(config.gain, config.max_gain),
                          std::log2(config.f_number * config.f_number / config.shutter_s)};
  m.vignetting = config.vignetting;
  m.chromatic_aberration = config.chromatic_aberration;
  m.bloom = config.bloom;
  m.jpeg_quality = config.jpeg_quality;
  if (config.depth_of_field)
    m.depth_of_field =
        DepthOfField{config.f_number, config.focus_distance, config.sensor_width_mm * camera.fx / double(camera.width)};
  return m;
}

CameraModel exposed_camera_model(const CameraModel& model, double ev100) {
  CameraModel m = model;
  if (!m.noise) return m;
  SensorNoise& n = *m.noise;
  const double gain = std::clamp(std::exp2(n.aperture_ev - ev100), n.gain, std::max(n.gain, n.max_gain));
  m.chroma = 1.0 / (1.0 + kChromaLossPerStop * std::log2(gain / n.gain));
  n.gain = gain;
  return m;
}

}  // namespace silva
