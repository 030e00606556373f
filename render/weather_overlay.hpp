#pragma once
/// @file Falling rain streaks and snowflakes drawn over one frame's linear RGB radiance, seeded per
/// frame; RGB only (labels and depth never see them).
#include <cstdint>

#include "core/types.hpp"
#include "render/lighting.hpp"
#include "render/sky.hpp"

namespace silva::render {

/// Share of the rain and snowfall a closed canopy lets through (drips and what blows in).
inline constexpr float kUnderCanopyFall = 0.25f;

/// The rain and snowfall of one frame: pure per-pixel queries keyed on (seed, frame key, pixel).
struct WeatherOverlay {
  /// Densities from `weather`, the light of streaks and flakes from `sky`, the pattern from
  /// (seed, frame_key), sizes from the image `height`. Under a canopy (`canopy`: the share of the sky
  /// light it takes at the camera, canopy_share_row) fewer drops and flakes fall past the lens
  /// (kUnderCanopyFall of them under a closed one) and the streaks catch less sky light.
  WeatherOverlay(const WeatherPreset& weather, const Sky& sky, uint64_t seed, uint64_t frame_key, int height,
                 float canopy = 0.0f);

  /// True when there is rain or snowfall to draw.
  bool active() const { return rain_ > 0.0f || snow_ > 0.0f; }
  /// Draws over `count` linear radiances of image row `v` starting at column 0.
  void apply_row(int v, Vec3f* radiance, int count) const;

 private:
  /// Coverage in [0, 1] of pixel (u, v) by a rain streak.
  float streak(int u, int v) const;
  /// Coverage in [0, 1] of pixel (u, v) by a snowflake.
  float flake(int u, int v) const;

  float rain_, snow_;
  uint32_t salt_;           ///< Frame-keyed hash salt.
  float streak_length_;     ///< Pixels, near layer.
  float flake_cell_;        ///< Pixels between flakes of the near layer.
  Vec3f streak_radiance_;   ///< Light of a rain streak (sky light caught by the drops).
  Vec3f flake_radiance_;    ///< Light of a snowflake (lit by sun and sky).
};

}  // namespace silva::render
