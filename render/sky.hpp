#pragma once
/// @file The sky of one frame: a Preetham clear sky (render/sky_model.hpp) tabulated once,
/// blended towards a CIE overcast sky by the cloud cover, the sun or moon disc, fbm clouds on a sky
/// plane and stars; the sun's illuminance from the same model; the ambient light of that sky and
/// the ground's bounce as an order-2 spherical-harmonics irradiance. Luminance kcd/m², illuminance klx.
#include <vector>

#include "core/types.hpp"
#include "render/lighting.hpp"
#include "render/sky_sh.hpp"

namespace silva::render {

/// The sky of one preset (weather already applied, see with_weather) with its per-frame constants
/// precomputed; all queries are pure and cost no transcendental function.
struct Sky {
  /// Tabulates the sky, the sun's illuminance and the ambient fit from `preset`.
  explicit Sky(const LightingPreset& preset);

  /// Sky radiance seen along unit world direction `dir` (what a depth-0 pixel shows).
  Vec3f radiance(const Vec3f& dir) const;
  /// The cloud-cover blend of clear and overcast sky only (no disc, cloud shapes or stars): the
  /// light fog scatters and surfaces receive.
  Vec3f diffuse(const Vec3f& dir) const;
  /// Irradiance (klx) from sky and ground on a surface with unit normal `n`, before occlusion.
  Vec3f ambient(const Vec3f& n) const { return ambient_sh.irradiance(n); }

  Vec3f to_sun;            ///< Unit direction towards the sun or moon.
  Vec3f sun_illuminance;   ///< Direct light at normal incidence, klx per channel (after clouds; 0 below the horizon).
  Vec3f horizon_radiance;  ///< Mean diffuse sky radiance just above the horizon (what rain streaks catch).
  Vec3f mean_radiance;     ///< Diffuse sky and ground bounce averaged over all directions (what fog scatters).
  IrradianceSH ambient_sh; ///< Sky above and ground bounce below, as irradiance.

 private:
  /// Clear-sky radiance along `dir` from the table (bilinear in sqrt(z) and sin(γ/2)).
  Vec3f clear(const Vec3f& dir) const;
  /// CIE overcast radiance along `dir`: zenith (1 + 2 cos θ) / 3, constant below the horizon.
  Vec3f overcast(const Vec3f& dir) const;
  /// Cloud density in [0, 1] along an upward direction.
  float cloud_density(const Vec3f& dir) const;
  /// Star radiance along a direction (0 almost everywhere).
  float star(const Vec3f& dir) const;

  LightingPreset preset_;
  std::vector<Vec3f> table_;  ///< Clear sky, kSkyRows (sqrt z) x kSkyCols (sin γ/2), row-major.
  Vec3f overcast_zenith_;     ///< Zenith radiance of the full overcast.
  Vec3f disc_radiance_;       ///< Radiance of the visible sun or moon disc.
  float disc_cos_;            ///< cos of the disc's angular radius.
  float disc_edge_cos_;       ///< cos of the anti-aliased outer edge of the disc.
};

}  // namespace silva::render
