#pragma once
/// @file Seeded 3D value noise for shaping meshes (rock displacement, bark bumps): the salt is
/// drawn from the generator's Rng, so shapes stay a pure function of the asset seed.
#include <cstdint>

#include "core/rng.hpp"
#include "core/types.hpp"

namespace silva::assets {

/// 3D value noise with fractal and ridged sums, all in known ranges.
class ShapeNoise {
 public:
  /// Draws the noise's salt from `rng`.
  explicit ShapeNoise(Rng& rng) : salt_(rng.next_u64()) {}
  /// Value noise in [-1, 1] (smooth interpolation of hashed lattice values).
  float value(const Vec3f& p) const;
  /// fBm of `octaves` value-noise layers (lacunarity 2, gain 0.5), normalised to [-1, 1].
  float fbm(const Vec3f& p, int octaves) const;
  /// Ridged multifractal: sum of (1 - |noise|)^2 layers, each weighted by the previous one,
  /// normalised to [0, 1]; sharp crests where the noise crosses zero.
  float ridged(const Vec3f& p, int octaves) const;

 private:
  /// Lattice value in [-1, 1] at an integer point.
  float lattice(int x, int y, int z) const;
  uint64_t salt_;
};

}  // namespace silva::assets
