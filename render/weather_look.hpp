#pragma once
/// @file What weather does to a lit surface, RGB only: a wet look (darker, more saturated albedo
/// and a smoother, glossier surface), puddles on the trail, and snow on upward-facing surfaces and the ground.
/// A muddy trail (TrailSurface::Muddy) is wet and holds water in its ruts in any weather.
#include "core/types.hpp"
#include "render/lighting.hpp"
#include "render/materials.hpp"

namespace silva::render {

/// The surface effects of one weather under one sky; pure per-pixel queries, no transcendentals.
struct WeatherLook {
  /// Reads wetness and snow cover from `weather`; `trail` is the trail's surface family.
  explicit WeatherLook(const WeatherPreset& weather, TrailSurface trail = TrailSurface::PackedEarth);

  /// True when the weather (or a muddy trail) changes surfaces at all.
  bool active() const { return wetness_ > 0.0f || snow_ > 0.0f || muddy_; }
  /// How wet surface point `s` is, 0 … 1: the weather's wetness, at least kMudWetness on a muddy trail.
  float wetness(const SurfacePoint& s) const;
  /// Standing water at surface point `s`, 0 … 1: puddles in hollows of the trail under rain (more of the
  /// trail the wetter the weather) and in a muddy trail's ruts (trail_standing_water), 0 elsewhere.
  float puddle(const SurfacePoint& s) const;
  /// The albedo of surface `s` of dry albedo `albedo` under this weather: wet, darker under a puddle's
  /// water (`puddle`), then snow by the
  /// normal's z and a world-space noise (less on the trodden trail, little on thin leaf cards,
  /// which bend under it and shed it).
  Vec3f albedo(const Vec3f& albedo, const SurfacePoint& s, float puddle) const;
  /// The GGX roughness of a surface of dry roughness `dry` and unit shading normal `n`: a water
  /// film smooths wet surfaces, most where they face up and hold it; a puddle's water is a mirror.
  float roughness(float dry, const Vec3f& n, float puddle = 0.0f) const;
  /// roughness() at surface point `s`, whose wetness may differ from the weather's (a muddy trail).
  float roughness(const SurfacePoint& s, float dry, const Vec3f& n, float puddle) const;

 private:
  /// roughness() of a surface of wetness `wet`.
  static float wet_roughness(float dry, const Vec3f& n, float puddle, float wet);

  float wetness_;
  float snow_;
  bool muddy_;
};

}  // namespace silva::render
