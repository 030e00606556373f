#pragma once
/// @file The radius function of a procedural rock: ridged multi-octave noise displacement of the
/// unit sphere, cut by a few planes (fracture facets). Kept apart so tests can bound it.
#include <vector>

#include "assets/shape_noise.hpp"

namespace silva::assets {

/// Bounds of RockShape::radius for any direction.
inline constexpr float kRockMinRadius = 0.55f, kRockMaxRadius = 1.3f;

/// One rock's shape before scaling: radius as a function of direction.
struct RockShape {
  ShapeNoise noise;           ///< Displacement noise.
  float frequency;            ///< Base frequency of the displacement (cycles per unit radius).
  float bulk, ridges;         ///< Amplitudes of the fBm (bulk) and ridged (crest) layers.
  std::vector<Vec3f> cuts;    ///< Fracture planes: unit normal n times the plane offset (0.6-0.95).
  /// Radius along unit direction d, within [kRockMinRadius, kRockMaxRadius].
  float radius(const Vec3f& d) const;
};

/// Draws a rock shape from `rng`: 2-5 fracture planes, bulk 0.1-0.22, ridges 0.05-0.12.
RockShape random_rock_shape(Rng& rng);

}  // namespace silva::assets
