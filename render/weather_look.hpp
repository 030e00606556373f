#pragma once
/// @file What weather does to a lit surface, RGB only: a wet look (darker, more saturated albedo
/// and a smoother, glossier surface) and snow on upward-facing surfaces and the ground.
#include "core/types.hpp"
#include "render/lighting.hpp"
#include "render/materials.hpp"

namespace silva::render {

/// The surface effects of one weather under one sky; pure per-pixel queries, no transcendentals.
struct WeatherLook {
  /// Reads wetness and snow cover from `weather`.
  explicit WeatherLook(const WeatherPreset& weather);

  /// True when the weather changes surfaces at all.
  bool active() const { return wetness_ > 0.0f || snow_ > 0.0f; }
  /// The albedo of surface `s` of dry albedo `albedo` under this weather: wet, then snow by the
  /// normal's z and a world-space noise (less on the trodden trail, little on thin leaf cards,
  /// which bend under it and shed it).
  Vec3f albedo(const Vec3f& albedo, const SurfacePoint& s) const;
  /// The GGX roughness of a surface of dry roughness `dry` and unit shading normal `n`: a water
  /// film smooths wet surfaces, most where they face up and hold it.
  float roughness(float dry, const Vec3f& n) const;

 private:
  float wetness_;
  float snow_;
};

}  // namespace silva::render
