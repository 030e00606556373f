#pragma once
/// @file Lighting presets (sun, sky, ambient, fog, clouds, exposure) and the built-in day/dusk/night.
#include <array>
#include <map>
#include <span>
#include <string>

#include "core/types.hpp"

namespace silva::render {

/// Linear RGB triple as stored in a preset (and in configs/lighting.toml as [r, g, b]).
using Rgb = std::array<float, 3>;

/// Defaults are the built-in `day` preset.
/// Everything that sets the mood of a capture: one directional light (the sun, or the moon at
/// night), an analytic sky, hemisphere ambient, exponential height fog, clouds and exposure.
/// Colours are linear RGB; intensities multiply them. configs/lighting.toml documents each field.
struct LightingPreset {
  float sun_elevation_deg = 55;     ///< Light elevation above the horizon (degrees).
  float sun_azimuth_deg = 135;      ///< Light azimuth, counter-clockwise from world +X (degrees).
  Rgb sun_color{1.0f, 0.95f, 0.88f}; ///< Colour of the direct light.
  float sun_intensity = 1.4f;       ///< Irradiance scale of the direct light.
  float sun_disc_deg = 0.6f;        ///< Angular diameter of the visible disc (sun or moon).
  float sun_disc_intensity = 50.0f; ///< Radiance of the disc relative to sun_color.
  float moon = 0.0f;                ///< 1 = draw the disc as a moon (flat, no glow), 0 = sun.
  Rgb sky_zenith{0.12f, 0.26f, 0.6f};  ///< Sky radiance straight up.
  Rgb sky_horizon{0.55f, 0.66f, 0.82f}; ///< Sky radiance at the horizon.
  float sky_intensity = 1.0f;       ///< Scale of the sky radiance (sky pixels and sky light).
  float sun_glow = 0.5f;            ///< Strength of the sun-coloured glow around the light.
  Rgb ground_color{0.1f, 0.08f, 0.05f};  ///< Light bounced up from the ground (hemisphere ambient).
  float ambient_intensity = 0.9f;   ///< Scale of the sky/ground hemisphere light on surfaces.
  float ao_strength = 0.8f;         ///< How much screen-space ambient occlusion darkens ambient light.
  float foliage_translucency = 0.35f;  ///< Fraction of the light reaching back-lit leaves.
  Rgb fog_color{0.62f, 0.7f, 0.82f}; ///< Fog colour away from the light.
  float fog_density = 0.004f;       ///< Fog extinction per metre at fog_height.
  float fog_height = 0.0f;          ///< World z where fog has fog_density (metres).
  float fog_height_falloff = 0.08f; ///< Exponential decay of fog density per metre of height.
  float fog_sun_scatter = 0.4f;     ///< How strongly fog turns light-coloured towards the light.
  float cloud_cover = 0.35f;        ///< Fraction of the sky covered by clouds, 0..1.
  float cloud_scale = 500.0f;       ///< Size of cloud features on the cloud plane (metres).
  Rgb cloud_color{1.0f, 1.0f, 1.0f};  ///< Albedo of clouds (lit by sun and sky).
  float star_density = 0.0f;        ///< Fraction of sky cells holding a star (night), 0..0.05.
  float exposure_ev = 0.0f;         ///< Camera exposure in stops (radiance x 2^ev before tone mapping).

  /// Field-wise equality.
  friend bool operator==(const LightingPreset&, const LightingPreset&) = default;
};

/// One named preset field: either a scalar or an RGB colour, with its TOML comment.
struct PresetField {
  const char* name;                       ///< Key in a [lighting.presets.<name>] table.
  float LightingPreset::* scalar;         ///< Member if the field is a number, else nullptr.
  Rgb LightingPreset::* colour;           ///< Member if the field is an [r, g, b] array, else nullptr.
  float min;                              ///< Smallest allowed value (each component for colours).
  float max;                              ///< Largest allowed value (each component for colours).
  const char* doc;                        ///< One-line description.
};

/// Every field of LightingPreset in declaration order (drives parsing, printing and checks).
std::span<const PresetField> preset_fields();

/// Built-in clear-sky midday preset.
LightingPreset preset_day();
/// Built-in low-sun, orange-horizon dusk preset.
LightingPreset preset_dusk();
/// Built-in moonlit night preset (dark blue sky, stars).
LightingPreset preset_night();
/// The built-in presets by name: "day", "dusk", "night".
std::map<std::string, LightingPreset> builtin_presets();

/// Unit world vector pointing from the scene towards the light (Z up, azimuth from +X, CCW).
Vec3f sun_direction(const LightingPreset& preset);

/// An Rgb as an Eigen vector.
inline Vec3f to_vec(const Rgb& c) { return Vec3f(c[0], c[1], c[2]); }

}  // namespace silva::render
