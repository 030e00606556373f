#pragma once
/// @file The camera model's last step on one image row: vignetting and sensor noise on the linear
/// signal, then the tone curve and sRGB (render/post.hpp's encode_srgb8_row).
#include <cstdint>
#include <vector>

#include "core/camera.hpp"
#include "core/camera_model.hpp"
#include "render/post.hpp"

namespace silva::render {

/// The noise scale of a sensor: full_well_e / gain electrons at full scale, read_noise_e^2.
NoiseScale noise_scale(const SensorNoise& sensor);

/// Vignetting factor of a pixel whose ray is (x, y, 1) in camera axes: 1 - s + s * cos^4 of the
/// ray's angle to the optical axis, cos^2 = 1 / (1 + x^2 + y^2).
float vignetting_factor(float x, float y, float strength);

/// Encodes rows of one frame; holds its own per-row buffers, so use one per thread.
class RowEncoder {
 public:
  /// For `camera`'s frame under `model` (its gain and chroma as exposed_camera_model gives them); noise drawn
  /// from the stream (seed, key); each channel's exposure times its `white_balance` gain.
  RowEncoder(const Camera& camera, const CameraModel& model, float exposure, uint64_t seed, uint64_t key,
             const Vec3f& white_balance = Vec3f::Ones());
  /// Encodes row v's camera.width linear radiances (3 floats each) into camera.width * 3 bytes.
  void encode(int v, const float* radiance, uint8_t* out);

 private:
  const Camera& camera_;
  uint64_t seed_, key_;
  float exposure_, vignetting_;
  Vec3f white_balance_;
  bool noise_;
  float chroma_;                   ///< Share of each pixel's colour kept (CameraModel::chroma).
  float own_weight_ = 1, shared_weight_ = 0;  ///< Noise draw weights: a channel's own, the three's sum.
  std::vector<float> desaturated_; ///< The row's radiance with chroma_ of its colour, when chroma_ < 1.
  RowExposure row_;
  std::vector<float> ray_x_;  ///< Per column: the ray's x at z = 1 (vignetting only).
  std::vector<float> scales_, normals_;
};

}  // namespace silva::render
