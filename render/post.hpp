#pragma once
/// @file Camera post-processing: exposure, seeded shot + read sensor noise on the linear signal,
/// ACES-fit filmic tone mapping and 8-bit sRGB encoding. All functions are pure.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/rng.hpp"
#include "core/types.hpp"

namespace silva::render {

/// Linear scale of an exposure in stops: 2^ev.
float exposure_scale(float exposure_ev);

/// Exposed signal at which the camera's image is white: the sky and sunlit leaves above it clip, as a
/// camera metering a forest lets them.
inline constexpr float kToneWhite = 1.0f;
/// 1 / the ACES fit at kToneWhite: the gain that maps kToneWhite to display white.
inline constexpr float kToneGain = float(1.0 / (2.54 / 3.16));

/// The camera's tone curve, x (exposed linear signal, >= 0) -> display-linear [0, 1]: Narkowicz's ACES
/// filmic fit times kToneGain, clipped at 1 (from x = kToneWhite on).
float tonemap_aces(float x);

/// Entries of the display-linear -> sRGB8 table.
inline constexpr int kSrgbTableSize = 16384;

/// Display-linear value (clamped to [0, 1]) -> 8-bit sRGB code: srgb8_table()[int(c * 16383 + 0.5)].
uint8_t linear_to_srgb8(float x);

/// The kSrgbTableSize codes linear_to_srgb8 looks up.
const uint8_t* srgb8_table();

/// Sensor noise in the encoder's units (render/camera_encode.hpp derives it from SensorNoise).
struct NoiseScale {
  float electrons_per_unit = 1;  ///< Electrons of an exposed signal of 1 (full scale): full_well_e / gain.
  float unit_per_electron = 1;   ///< 1 / electrons_per_unit.
  float read_variance = 0;       ///< read_noise_e^2.
};

/// One exposed linear value `x` with sensor noise: x + normal * sqrt(min(max(x, 0), 1) *
/// electrons_per_unit + read_variance) * unit_per_electron, `normal` a standard normal draw.
float noisy_signal(float x, float normal, const NoiseScale& noise);

/// What encode_srgb8_row does to each value before the tone curve.
struct RowExposure {
  float exposure = 1;               ///< Scale of every value when `scales` is null.
  const float* scales = nullptr;    ///< Per-value scale (exposure x vignetting), or null.
  const float* normals = nullptr;   ///< Per-value standard normal draws, or null for no noise.
  NoiseScale noise;                 ///< The noise's scale (read when `normals` is set).
};

/// Encodes `count` linear radiances (3 floats each) as sRGB8 bytes, per value k
/// linear_to_srgb8(tonemap_aces(noisy_signal(radiance[k] * scale_k, normals[k], noise))) (no noise
/// term without normals), on SIMD lanes with the scalar functions' operations, so the bytes are theirs.
void encode_srgb8_row(const float* radiance, size_t count, const RowExposure& row, uint8_t* out);

/// The Highway target encode_srgb8_row dispatches to now.
int64_t encode_simd_target();

/// The sensor noise stream key of one frame: hash of (sequence name, frame number).
uint64_t noise_key(std::string_view sequence, uint64_t frame);

/// Standard normal value number `index` of 65536 equal-probability bins (bin-centre quantiles,
/// rescaled so the 65536 values have mean 0 and variance 1 exactly in double precision).
float normal_quantile(uint16_t index);

/// Standard normal draws for the R, G, B channels of pixel `pixel`:
/// rng_bits(seed, key, Purpose::SensorNoise, pixel) split into three 16-bit quantile indices.
Vec3f sensor_normals(uint64_t seed, uint64_t key, uint64_t pixel);

/// sensor_normals(seed, key, pixel) from the stream RngStreamBits(seed, key, Purpose::SensorNoise).
Vec3f sensor_normals(const RngStreamBits& stream, uint64_t pixel);

}  // namespace silva::render
