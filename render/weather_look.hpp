#pragma once
/// @file What weather does to a lit surface, RGB only: a wet look (darker, more saturated albedo
/// and a sky sheen on upward surfaces) and snow on upward-facing surfaces and the ground.
#include "core/types.hpp"
#include "render/lighting.hpp"
#include "render/materials.hpp"
#include "render/sky.hpp"

namespace silva::render {

/// The surface effects of one weather under one sky; pure per-pixel queries, no transcendentals.
struct WeatherLook {
  /// Reads wetness and snow cover from `weather`, the light wet surfaces mirror from `sky`.
  WeatherLook(const WeatherPreset& weather, const Sky& sky);

  /// True when the weather changes surfaces at all.
  bool active() const { return wetness_ > 0.0f || snow_ > 0.0f; }
  /// The albedo of surface `s` of dry albedo `albedo` under this weather: wet, then snow by the
  /// normal's z and a world-space noise (less on the trodden trail).
  Vec3f albedo(const Vec3f& albedo, const SurfacePoint& s) const;
  /// Sky light mirrored by a wet surface of unit normal `n` seen along unit `view_dir` (Schlick
  /// Fresnel, upward surfaces only), scaled by the ambient visibility `ambient_visible`.
  Vec3f sheen(const Vec3f& n, const Vec3f& view_dir, float ambient_visible) const;

 private:
  float wetness_;
  float snow_;
  Vec3f horizon_;  ///< Sky radiance just above the horizon.
};

}  // namespace silva::render
