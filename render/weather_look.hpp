#pragma once
/// @file What weather does to a lit surface, RGB only: a wet look (darker, more saturated albedo
/// and a smoother, glossier surface), puddles on the trail, and snow on upward-facing surfaces and the ground.
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
  /// Standing water at surface point `s`, 0 … 1: puddles in hollows of the trail under rain (more of the
  /// trail the wetter the weather), 0 elsewhere and when dry.
  float puddle(const SurfacePoint& s) const;
  /// The albedo of surface `s` of dry albedo `albedo` under this weather: wet, darker under a puddle's
  /// water (`puddle`), then snow by the
  /// normal's z and a world-space noise (less on the trodden trail, little on thin leaf cards,
  /// which bend under it and shed it).
  Vec3f albedo(const Vec3f& albedo, const SurfacePoint& s, float puddle) const;
  /// The GGX roughness of a surface of dry roughness `dry` and unit shading normal `n`: a water
  /// film smooths wet surfaces, most where they face up and hold it; a puddle's water is a mirror.
  float roughness(float dry, const Vec3f& n, float puddle = 0.0f) const;

 private:
  float wetness_;
  float snow_;
};

}  // namespace silva::render
