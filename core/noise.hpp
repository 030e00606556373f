#pragma once
/// @file 2D simplex noise and its fractal (fBm) sum: pure, deterministic functions of position.
/// Only exact or correctly rounded operations are used (no FMA), so values are bit-identical
/// on every target and thread count.

#include <cstdint>

namespace silva {

/// 2D simplex noise (Gustavson's formulation with Perlin's permutation), value in [-1, 1].
double simplex2(double x, double y);

/// The tables simplex2 reads, for versions on SIMD lanes that must return its bits.
struct SimplexTables {
  const uint8_t* permutation;   ///< Perlin's permutation of 0..255 (256 entries).
  const double (*gradients)[2]; ///< The 12 gradient directions (x, y).
};

/// simplex2's tables.
SimplexTables simplex2_tables();

/// Parameters of a fractal Brownian motion sum of simplex octaves.
struct FbmParams {
  int octaves = 6;            ///< Number of octaves (>= 1).
  double lacunarity = 2.0;    ///< Frequency factor from one octave to the next.
  double persistence = 0.5;   ///< Amplitude factor from one octave to the next.
  double frequency = 0.01;    ///< Base frequency, cycles per unit of x/y.
  double offset_x = 0.0;      ///< Noise-space offset added after scaling (seeds the field).
  double offset_y = 0.0;      ///< Noise-space offset added after scaling (seeds the field).
};

/// Sum of octaves normalised by the sum of amplitudes: value in [-1, 1].
double fbm2(const FbmParams& p, double x, double y);

}  // namespace silva
