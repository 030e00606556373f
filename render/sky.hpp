#pragma once
/// @file Analytic sky: zenith-horizon gradient, sun glow, sun or moon disc, fbm clouds on a sky
/// plane, optional stars; plus the hemisphere sky/ground light that surfaces receive.
#include "core/types.hpp"
#include "render/lighting.hpp"

namespace silva::render {

/// The sky of one preset with its per-frame constants precomputed; all queries are pure.
struct Sky {
  /// Precomputes colours, the light direction and the disc size from `preset`.
  explicit Sky(const LightingPreset& preset);

  /// Sky radiance seen along unit world direction `dir` (what a depth-0 pixel shows).
  Vec3f radiance(const Vec3f& dir) const;
  /// Gradient plus glow only (no disc, clouds or stars): the colour fog and ambient blend towards.
  Vec3f gradient(const Vec3f& dir) const;
  /// Hemisphere light on a surface with unit normal `n`: sky from above, ground bounce from below.
  Vec3f ambient(const Vec3f& n) const;

  Vec3f to_sun;        ///< Unit direction towards the sun or moon.
  Vec3f sun_radiance;  ///< sun_color x sun_intensity, faded out below the horizon.
  Vec3f zenith;        ///< Zenith radiance (x sky_intensity).
  Vec3f horizon;       ///< Horizon radiance (x sky_intensity).
  Vec3f sky_light;     ///< Hemisphere light from above (x ambient_intensity).
  Vec3f ground_light;  ///< Hemisphere light from below (x ambient_intensity).

 private:
  /// Cloud density in [0, 1] along an upward direction.
  float cloud_density(const Vec3f& dir) const;
  /// Star radiance along a direction (0 almost everywhere).
  float star(const Vec3f& dir) const;

  LightingPreset preset_;
  Vec3f cloud_lit_;     ///< Radiance of a fully dense cloud.
  float disc_cos_;      ///< cos of the disc's angular radius.
  float disc_edge_cos_; ///< cos of the anti-aliased outer edge of the disc.
};

}  // namespace silva::render
