#pragma once
/// @file Lighting presets (sun, sky, ambient, fog, clouds, exposure), weather presets (clouds, fog,
/// wet and snowy surfaces, falling rain or snow) and the built-in ones.
#include <array>
#include <map>
#include <span>
#include <string>

#include "core/types.hpp"

namespace silva::render {

/// Linear RGB triple as stored in a preset (and in configs/lighting.toml as [r, g, b]).
using Rgb = std::array<float, 3>;

/// Defaults are the built-in `clear` weather: it changes nothing.
/// What the weather adds to a time of day: more cloud, more fog, a camera exposure shift, and
/// looks that change RGB only (wet or snowy surfaces, falling rain or snow), never labels or depth.
struct WeatherPreset {
  float cloud_cover_min = 0.0f;            ///< The sky's cloud cover is at least this (0..1).
  float cloud_transmittance_scale = 1.0f;  ///< Multiplies the time of day's cloud_transmittance (darker clouds).
  float fog_density_scale = 1.0f;          ///< Multiplies the time of day's fog_density.
  float ev100_offset = 0.0f;               ///< Added to the time of day's ev100 (negative = brighter image).
  float wetness = 0.0f;                    ///< Wet look: darker, more saturated albedo, lower roughness (0..1).
  float snow_cover = 0.0f;                 ///< Snow on upward-facing surfaces and the ground (0..1).
  float rain_streaks = 0.0f;               ///< Density of falling rain streaks drawn over the RGB (0..1).
  float snowfall = 0.0f;                   ///< Density of falling snowflakes drawn over the RGB (0..1).

  /// Field-wise equality.
  friend bool operator==(const WeatherPreset&, const WeatherPreset&) = default;
};

/// Defaults are the built-in `day` preset (with clear weather).
/// Everything that sets the mood of a capture: one directional light (the sun, or the moon at
/// night) and a Preetham clear sky from its elevation and the turbidity, blended towards a CIE
/// overcast sky by the cloud cover; ambient light from a spherical-harmonics fit of that sky and
/// the ground's bounce; exponential height fog; procedural clouds; a physical exposure (EV100).
/// Light is in physical units: luminance kcd/m², illuminance klx. configs/lighting.toml documents each field.
struct LightingPreset {
  float sun_elevation_deg = 55;      ///< Light elevation above the horizon (degrees).
  float sun_azimuth_deg = 135;       ///< Light azimuth, counter-clockwise from world +X (degrees).
  float turbidity = 3.0f;            ///< Atmospheric turbidity of the sky model (2 = very clear .. 10 = hazy).
  Rgb sun_tint{1.0f, 1.0f, 1.0f};    ///< Multiplies the sky model's sun colour.
  float sun_intensity = 1.0f;        ///< Multiplies the sun's illuminance (1 = the sun; ~2.5e-6 = a full moon).
  float sun_disc_deg = 0.6f;         ///< Angular diameter of the visible disc (sun or moon).
  Rgb sky_tint{1.0f, 1.0f, 1.0f};    ///< Multiplies the sky model's colour (sky pixels and sky light).
  float sky_intensity = 1.0f;        ///< Multiplies the sky model's luminance (sky pixels and sky light).
  Rgb ground_albedo{0.12f, 0.11f, 0.07f};  ///< Albedo of the ground that bounces light up onto surfaces.
  float ambient_intensity = 1.0f;    ///< Multiplies the sky and ground light on surfaces (1 = physical).
  float ao_strength = 0.8f;          ///< How much screen-space ambient occlusion darkens ambient light.
  float foliage_translucency = 0.35f;  ///< Fraction of the light reaching back-lit leaves.
  Rgb fog_tint{1.0f, 1.0f, 1.0f};    ///< Multiplies the light the fog scatters (sky, ground bounce, sun).
  float fog_density = 0.004f;        ///< Fog extinction per metre at fog_height.
  float fog_height = 0.0f;           ///< World z where fog has fog_density (metres).
  float fog_height_falloff = 0.08f;  ///< Exponential decay of fog density per metre of height.
  float fog_sun_scatter = 0.4f;      ///< How strongly fog turns light-coloured towards the light.
  float cloud_cover = 0.35f;         ///< Fraction of the sky covered by clouds, 0..1 (1 = overcast, no direct light).
  float cloud_scale = 500.0f;        ///< Size of cloud features on the cloud plane (metres).
  Rgb cloud_color{1.0f, 1.0f, 1.0f}; ///< Albedo of clouds.
  float cloud_transmittance = 0.35f; ///< Fraction of the clear-sky daylight a full overcast lets through.
  float star_density = 0.0f;         ///< Fraction of sky cells holding a star (night), 0..0.05.
  float ev100 = 13.5f;               ///< Camera exposure value at ISO 100 (sunny day 15; 13.5 exposes a forest's shade; dusk ~11.5, moonlight ~ -2).
  WeatherPreset weather;             ///< The weather on top (lighting.weather); not part of a [lighting.presets] table.

  /// Field-wise equality.
  friend bool operator==(const LightingPreset&, const LightingPreset&) = default;
};

/// One named field of a preset of type T: either a scalar or an RGB colour, with its TOML comment.
template <class T>
struct PresetFieldOf {
  const char* name;        ///< Key in a preset table.
  float T::* scalar;       ///< Member if the field is a number, else nullptr.
  Rgb T::* colour;         ///< Member if the field is an [r, g, b] array, else nullptr.
  float min;               ///< Smallest allowed value (each component for colours).
  float max;               ///< Largest allowed value (each component for colours).
  const char* doc;         ///< One-line description.
};

/// A field of a [lighting.presets.<name>] table.
using PresetField = PresetFieldOf<LightingPreset>;
/// A field of a [lighting.weather_presets.<name>] table.
using WeatherField = PresetFieldOf<WeatherPreset>;

/// Every field of LightingPreset except `weather`, in declaration order (drives parsing, printing and checks).
std::span<const PresetField> preset_fields();
/// Every field of WeatherPreset in declaration order.
std::span<const WeatherField> weather_fields();

/// Built-in clear-sky midday preset.
LightingPreset preset_day();
/// Built-in low-sun dusk preset: orange light, dimmer than day.
LightingPreset preset_dusk();
/// Built-in moonlit night preset (dark blue sky, stars).
LightingPreset preset_night();
/// The built-in presets by name: "day", "dusk", "night".
std::map<std::string, LightingPreset> builtin_presets();
/// The built-in weather presets by name: "clear", "overcast", "mist", "rain", "snow".
std::map<std::string, WeatherPreset> builtin_weathers();

/// `preset` with its weather's cloud, fog and exposure changes applied (the looks stay in `weather`).
LightingPreset with_weather(const LightingPreset& preset);

/// Linear radiance (kcd/m²) -> tone-curve input: 2 / (1.2 · 2^EV100 cd/m²), the ISO 2720
/// saturation luminance with a factor 2 of headroom for the filmic curve's shoulder.
float exposure_multiplier(float ev100);

/// Unit world vector pointing from the scene towards the light (Z up, azimuth from +X, CCW).
Vec3f sun_direction(const LightingPreset& preset);

/// An Rgb as an Eigen vector.
inline Vec3f to_vec(const Rgb& c) { return Vec3f(c[0], c[1], c[2]); }

}  // namespace silva::render
