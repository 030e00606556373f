#include "render/camera_encode.hpp"

#include <cmath>

namespace silva::render {

NoiseScale noise_scale(const SensorNoise& sensor) {
  const double electrons = sensor.full_well_e / sensor.gain;
  return {float(electrons), float(1.0 / electrons), float(sensor.read_noise_e * sensor.read_noise_e)};
}

float vignetting_factor(float x, float y, float strength) {
  const float cos2 = 1.0f / (1.0f + x * x + y * y);
  return 1.0f - strength + strength * (cos2 * cos2);
}

RowEncoder::RowEncoder(const Camera& camera, const CameraModel& model, float exposure, uint64_t seed, uint64_t key)
    : camera_(camera),
      seed_(seed),
      key_(key),
      exposure_(exposure),
      vignetting_(float(model.vignetting)),
      noise_(model.noise.has_value()) {
  row_.exposure = exposure;
  if (noise_) {
    row_.noise = noise_scale(*model.noise);
    normals_.resize(size_t(camera.width) * 3);
    row_.normals = normals_.data();
  }
  if (vignetting_ > 0.0f) {
    scales_.resize(size_t(camera.width) * 3);
    row_.scales = scales_.data();
    ray_x_.resize(size_t(camera.width));
    for (int u = 0; u < camera.width; ++u) ray_x_[size_t(u)] = float((double(u) + 0.5 - camera.cx) / camera.fx);
  }
}

void RowEncoder::encode(int v, const float* radiance, uint8_t* out) {
  const size_t w = size_t(camera_.width);
  if (noise_) {
    const uint64_t first = uint64_t(v) * w;
    for (size_t u = 0; u < w; ++u) {
      const Vec3f z = sensor_normals(seed_, key_, first + u);
      normals_[3 * u] = z.x();
      normals_[3 * u + 1] = z.y();
      normals_[3 * u + 2] = z.z();
    }
  }
  if (vignetting_ > 0.0f) {
    const float y = float((double(v) + 0.5 - camera_.cy) / camera_.fy);
    for (size_t u = 0; u < w; ++u) {
      const float scale = exposure_ * vignetting_factor(ray_x_[u], y, vignetting_);
      scales_[3 * u] = scales_[3 * u + 1] = scales_[3 * u + 2] = scale;
    }
  }
  encode_srgb8_row(radiance, w, row_, out);
}

}  // namespace silva::render
