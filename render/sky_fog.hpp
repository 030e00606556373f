#pragma once
/// @file Exponential height fog seen from one camera, coloured by the sky towards the sun/horizon.
#include "core/types.hpp"
#include "render/fog_amounts.hpp"
#include "render/lighting.hpp"
#include "render/sky.hpp"

namespace silva::render {

/// Fraction of the open sky's light (and the sun's) that the air under the canopy receives: fog
/// inside a forest is shaded by the crowns like the floor beneath it, so mist never outshines the
/// surfaces it hangs between (night mist stays as dark as the night).
inline constexpr float kFogCanopyOpenness = 0.45f;
/// Share of the fog's light the canopy over a surface takes from the fog in front of it (the air under trees is
/// in their shade, but lit sideways from gaps and the open).
inline constexpr float kFogCanopyShade = 0.6f;

/// Mean path length of diffuse light through a fog column, in units of its vertical optical depth.
inline constexpr double kDiffuseFogPath = 1.5;
/// The sun's path through the fog column is depth / max(sin elevation, this).
inline constexpr double kMinFogSunSine = 0.1;

/// Fractions of the sky's and the sun's light that reach the fog at the camera through the fog above it.
struct HeightFogLight {
  float diffuse = 1.0f;  ///< Sky and ground light: exp(-kDiffuseFogPath x column depth).
  float sun = 1.0f;      ///< Direct light: exp(-column depth / max(sin elevation, kMinFogSunSine)).
};

/// Dense fog shades itself: the light it scatters towards the camera has first crossed the fog column
/// above the camera (optical depth fog_density e^(-falloff (z - fog_height)) / falloff), so a thick mist
/// under a dim sky or the moon stays dark instead of glowing like a thin haze.
HeightFogLight fog_light_transmittance(const LightingPreset& preset, const Vec3f& to_sun, float camera_z);

/// Height fog of one preset and camera position: density(z) = fog_density * exp(-falloff (z - fog_height)).
struct HeightFog {
  /// Precomputes the camera-height factor of the fog integral.
  HeightFog(const LightingPreset& preset, const Sky& sky, const Vec3f& camera_position);
  /// Fraction in [0, 1) of the view towards `point` replaced by fog (optical depth integrated
  /// along the straight ray from the camera, in closed form; see fog_amounts).
  float amount(const Vec3f& point) const;
  /// amount() of `count` points at once into `out` (SIMD lanes; the same values).
  void amounts(const Vec3f* points, size_t count, float* out) const { fog_amounts(params_, points, count, out); }
  /// Fog radiance along unit view direction `dir`: the light arriving from all directions (sky,
  /// ground bounce, sun) scattered evenly, times kFogCanopyOpenness, plus a forward lobe towards
  /// the sun; each light dimmed by the fog above (fog_light_transmittance); times fog_tint.
  Vec3f color(const Vec3f& dir) const;
  /// `surface` seen through fog of amount `amount` (from amount()/amounts()) along unit direction `dir`, the
  /// fog lit by `light` of its light (1 - the canopy share over a surface under trees: the air there is in shade).
  Vec3f apply(const Vec3f& surface, float amount, const Vec3f& dir, float light = 1.0f) const;
  /// The isotropic part of color(), kcd/m².
  const Vec3f& in_scatter() const { return in_scatter_; }
  /// The peak of color()'s forward lobe towards the sun, kcd/m².
  const Vec3f& sun_scatter() const { return sun_scatter_; }

 private:
  const Sky& sky_;
  FogAmountParams params_;  ///< Camera, falloff and density at the camera height.
  HeightFogLight light_;    ///< What reaches the fog through the fog above.
  Vec3f in_scatter_;   ///< Isotropic in-scattered radiance, kcd/m².
  Vec3f sun_scatter_;  ///< Peak of the forward lobe towards the sun, kcd/m².
};

}  // namespace silva::render
