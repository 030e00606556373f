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

RowEncoder::RowEncoder(const Camera& camera, const CameraModel& model, float exposure, uint64_t seed, uint64_t key,
                       const Vec3f& white_balance)
    : camera_(camera),
      seed_(seed),
      key_(key),
      exposure_(exposure),
      vignetting_(float(model.vignetting)),
      white_balance_(white_balance),
      noise_(model.noise.has_value()) {
  row_.exposure = exposure;
  if (noise_) {
    row_.noise = noise_scale(*model.noise);
    normals_.resize(size_t(camera.width) * 3);
    row_.normals = normals_.data();
  }
  if (vignetting_ > 0.0f || white_balance_ != Vec3f::Ones()) {
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
    const RngStreamBits stream(seed_, key_, uint64_t(Purpose::SensorNoise));
    for (size_t u = 0; u < w; ++u) {
      const Vec3f z = sensor_normals(stream, first + u);
      normals_[3 * u] = z.x();
      normals_[3 * u + 1] = z.y();
      normals_[3 * u + 2] = z.z();
    }
  }
  if (row_.scales) {
    const float y = float((double(v) + 0.5 - camera_.cy) / camera_.fy);
    for (size_t u = 0; u < w; ++u) {
      const float scale = vignetting_ > 0.0f ? exposure_ * vignetting_factor(ray_x_[u], y, vignetting_) : exposure_;
      for (int k = 0; k < 3; ++k) scales_[3 * u + size_t(k)] = scale * white_balance_[k];
    }
  }
  encode_srgb8_row(radiance, w, row_, out);
}

}  // namespace silva::render
