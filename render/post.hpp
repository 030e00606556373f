#pragma once
/// @file Camera post-processing: exposure, ACES-fit filmic tone mapping, seeded Gaussian film
/// grain (thesis 3.4) and 8-bit sRGB encoding. All functions are pure.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/types.hpp"

namespace silva::render {

/// Linear scale of an exposure in stops: 2^ev.
float exposure_scale(float exposure_ev);

/// Narkowicz's ACES filmic fit, x (linear, >= 0) -> display-linear [0, 1].
float tonemap_aces(float x);

/// Entries of the display-linear -> sRGB8 table.
inline constexpr int kSrgbTableSize = 16384;

/// Display-linear value (clamped to [0, 1]) -> 8-bit sRGB code: srgb8_table()[int(c * 16383 + 0.5)].
uint8_t linear_to_srgb8(float x);

/// The kSrgbTableSize codes linear_to_srgb8 looks up.
const uint8_t* srgb8_table();

/// Encodes `count` linear radiances (3 floats each) as sRGB8 bytes, per channel
/// linear_to_srgb8(tonemap_aces(radiance * exposure) + grain) with `grain` (3 floats per pixel,
/// or null for none), on SIMD lanes with the scalar functions' operations, so the bytes are theirs.
void encode_srgb8_row(const float* radiance, const float* grain, size_t count, float exposure, uint8_t* out);

/// The Highway target encode_srgb8_row dispatches to now.
int64_t encode_simd_target();

/// The grain stream key of one frame: hash of (sequence name, frame number).
uint64_t grain_key(std::string_view sequence, uint64_t frame);

/// Standard normal value number `index` of 65536 equal-probability bins (bin-centre quantiles,
/// rescaled so the 65536 values have mean 0 and variance 1 exactly in double precision).
float grain_quantile(uint16_t index);

/// Zero-mean Gaussian grain of std-dev `sigma` for the R, G, B channels of pixel `pixel`:
/// rng_bits(seed, key, Purpose::FilmGrain, pixel) split into three 16-bit quantile indices.
Vec3f film_grain(uint64_t seed, uint64_t key, uint64_t pixel, float sigma);

}  // namespace silva::render
