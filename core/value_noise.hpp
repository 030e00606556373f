#pragma once
/// @file Stateless value noise for procedural shading: hashed integer lattice points, smooth
/// interpolation, fractal sums. Pure functions of their arguments (no tables, no global state).
#include <cmath>
#include <cstdint>

namespace silva {

/// Well-mixed 32-bit hash of a 3D integer lattice point and a salt (murmur3-style finaliser).
inline uint32_t lattice_hash(int32_t x, int32_t y, int32_t z, uint32_t salt) {
  uint32_t h = uint32_t(x) * 0x8da6b343u ^ uint32_t(y) * 0xd8163841u ^ uint32_t(z) * 0xcb1ab31fu;
  h ^= salt * 0x9e3779b9u;
  h ^= h >> 16;
  h *= 0x85ebca6bu;
  h ^= h >> 13;
  h *= 0xc2b2ae35u;
  h ^= h >> 16;
  return h;
}

/// Lattice value in [0, 1) from a hash.
inline float lattice_value(uint32_t h) { return float(h >> 8) * (1.0f / 16777216.0f); }

/// Smooth (C1) interpolation weight of a fraction in [0, 1].
inline float smooth_weight(float t) { return t * t * (3.0f - 2.0f * t); }

/// Linear interpolation a + (b - a) t.
inline float mix(float a, float b, float t) { return a + (b - a) * t; }

/// 2D value noise in [0, 1): bilinear blend of hashed lattice values with smooth weights.
float value_noise2(float x, float y, uint32_t salt);

/// 3D value noise in [0, 1).
float value_noise3(float x, float y, float z, uint32_t salt);

/// A noise value with its gradient (per unit of the noise's own coordinates).
struct NoiseGradient {
  float value;       ///< The noise, as value_noise3 gives it.
  float dx, dy, dz;  ///< Partial derivatives.
};

/// value_noise3 (the same value) and its analytic gradient.
NoiseGradient value_noise3_gradient(float x, float y, float z, uint32_t salt);

/// Fractal sum of `octaves` 2D value-noise layers (lacunarity 2, gain 0.5), normalised to [0, 1).
float fbm2(float x, float y, int octaves, uint32_t salt);

/// Fractal sum of `octaves` 3D value-noise layers (lacunarity 2, gain 0.5), normalised to [0, 1).
float fbm3(float x, float y, float z, int octaves, uint32_t salt);

}  // namespace silva
