#include "render/camera_encode.hpp"

#include <algorithm>
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
      noise_(model.noise.has_value()),
      chroma_(float(model.chroma)) {
  // Noise kept as colour: chroma of each channel's own draw, the rest the draws' shared (luma) part,
  // (z_r + z_g + z_b) / sqrt(3), scaled back to unit variance per channel.
  const double own = std::sqrt(model.chroma), shared = std::sqrt(1.0 - std::min(model.chroma, 1.0));
  const double norm = 1.0 / std::sqrt(1.0 + 2.0 * own * shared / std::sqrt(3.0));
  own_weight_ = float(own * norm);
  shared_weight_ = float(shared / std::sqrt(3.0) * norm);
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
      const float shared = chroma_ < 1.0f ? (z.x() + z.y() + z.z()) * shared_weight_ : 0.0f;
      for (int c = 0; c < 3; ++c) normals_[3 * u + size_t(c)] = z[c] * own_weight_ + shared;
    }
  }
  if (row_.scales) {
    const float y = float((double(v) + 0.5 - camera_.cy) / camera_.fy);
    for (size_t u = 0; u < w; ++u) {
      const float scale = vignetting_ > 0.0f ? exposure_ * vignetting_factor(ray_x_[u], y, vignetting_) : exposure_;
      for (int k = 0; k < 3; ++k) scales_[3 * u + size_t(k)] = scale * white_balance_[k];
    }
  }
  if (chroma_ < 1.0f) {
    desaturated_.resize(3 * w);
    for (size_t k = 0; k < 3 * w; k += 3) {
      const float y = 0.2126f * radiance[k] + 0.7152f * radiance[k + 1] + 0.0722f * radiance[k + 2];
      for (size_t c = 0; c < 3; ++c) desaturated_[k + c] = y + chroma_ * (radiance[k + c] - y);
    }
    radiance = desaturated_.data();
  }
  encode_srgb8_row(radiance, w, row_, out);
}

}  // namespace silva::render
