#pragma once
/// @file The lighting of each frame of a run: the selected preset, or one drawn per frame from
/// [lighting.randomize]'s ranges (seeded by seed, sequence and frame), and how the camera exposes
/// and white-balances it.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/config.hpp"
#include "core/types.hpp"
#include "render/lighting.hpp"

namespace silva::render {

/// What a run lights its frames with: the preset lighting.time_of_day and lighting.weather name,
/// the exposure mode, and the ranges each frame draws from when lighting.randomize is enabled.
struct RunLighting {
  LightingPreset preset;                   ///< The time of day with lighting.weather's weather.
  std::string time_of_day = "day";         ///< lighting.time_of_day.
  std::string weather = "clear";           ///< lighting.weather.
  bool auto_exposure = false;              ///< lighting.exposure = "auto".
  float exposure_compensation_ev = 0.0f;   ///< lighting.exposure_compensation (positive = brighter).
  LightingRandomizeConfig randomize;       ///< [lighting.randomize] (its `enabled` switches the draws on).
  std::vector<WeatherPreset> weather_choices;  ///< The presets randomize.weathers names, in its order.
};

/// The lighting of one frame.
struct FrameLighting {
  LightingPreset preset;                   ///< Time of day (drawn sun, clouds, fog) with the frame's weather.
  std::string time_of_day;                 ///< The time-of-day preset's name.
  std::string weather;                     ///< The weather preset's name (drawn when randomised).
  bool auto_exposure = false;              ///< Exposure metered from the frame (else preset.ev100 with the weather's offset).
  float exposure_compensation_ev = 0.0f;   ///< EV added to the image's brightness (lighting's and the drawn offset).
  float fog_density_scale = 1.0f;          ///< The drawn factor on the time of day's fog_density (1 when not drawn).
  float white_balance_k = kNeutralWhiteK;  ///< Colour temperature the camera balances for (kNeutralWhiteK = none).
  Vec3f white_balance = Vec3f::Ones();     ///< Per-channel gains of that white balance (exactly 1 when neutral).
  bool randomized = false;                 ///< Whether the values were drawn for this frame.

  /// The colour temperature (K) that leaves colours as they are (the sRGB white, D65).
  static constexpr float kNeutralWhiteK = 6504.0f;
};

/// The frame's lighting: `run`'s preset as it is, or, when run.randomize.enabled, with the sun's
/// elevation and azimuth, the cloud cover, a fog-density factor, an exposure offset and a white
/// balance each drawn uniformly from its [min, max], and the weather drawn from weather_choices by
/// weight, from the stream keyed on (seed, noise_key(sequence, frame)); so a frame's lighting never
/// depends on threads, shards or resume.
FrameLighting frame_lighting(const RunLighting& run, uint64_t seed, std::string_view sequence, uint64_t frame);

/// Linear-RGB gains of a camera white-balanced for black-body light of `kelvin` (Planckian locus
/// by Kim et al. 2002, 1667 … 25000 K): white(6504 K) / white(kelvin) per channel, scaled to unit
/// Rec.709 luminance. Below 6504 K the image turns bluer, above it warmer.
Vec3f white_balance_gains(float kelvin);

}  // namespace silva::render
