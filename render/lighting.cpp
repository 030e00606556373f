#include "render/lighting.hpp"

#include <cmath>

namespace silva::render {

namespace {
using P = LightingPreset;
constexpr PresetField kFields[] = {
    {"sun_elevation_deg", &P::sun_elevation_deg, nullptr, -90.0f, 90.0f, "light elevation above the horizon, degrees"},
    {"sun_azimuth_deg", &P::sun_azimuth_deg, nullptr, -360.0f, 360.0f, "light azimuth, degrees counter-clockwise from world +X"},
    {"sun_color", nullptr, &P::sun_color, 0.0f, 100.0f, "colour of the direct light, linear RGB"},
    {"sun_intensity", &P::sun_intensity, nullptr, 0.0f, 1000.0f, "irradiance scale of the direct light"},
    {"sun_disc_deg", &P::sun_disc_deg, nullptr, 0.0f, 20.0f, "angular diameter of the visible sun/moon disc, degrees"},
    {"sun_disc_intensity", &P::sun_disc_intensity, nullptr, 0.0f, 100000.0f, "radiance of the disc relative to sun_color"},
    {"moon", &P::moon, nullptr, 0.0f, 1.0f, "1 = draw the disc as a moon (no glow), 0 = sun"},
    {"sky_zenith", nullptr, &P::sky_zenith, 0.0f, 100.0f, "sky radiance straight up, linear RGB"},
    {"sky_horizon", nullptr, &P::sky_horizon, 0.0f, 100.0f, "sky radiance at the horizon, linear RGB"},
    {"sky_intensity", &P::sky_intensity, nullptr, 0.0f, 1000.0f, "scale of the sky radiance (sky pixels and sky light)"},
    {"sun_glow", &P::sun_glow, nullptr, 0.0f, 100.0f, "strength of the light-coloured glow around the sun"},
    {"ground_color", nullptr, &P::ground_color, 0.0f, 100.0f, "light bounced up from the ground (hemisphere ambient), linear RGB"},
    {"ambient_intensity", &P::ambient_intensity, nullptr, 0.0f, 1000.0f, "scale of the sky/ground hemisphere light on surfaces"},
    {"ao_strength", &P::ao_strength, nullptr, 0.0f, 1.0f, "how much ambient occlusion darkens ambient light"},
    {"foliage_translucency", &P::foliage_translucency, nullptr, 0.0f, 1.0f, "fraction of the light reaching back-lit leaves"},
    {"fog_color", nullptr, &P::fog_color, 0.0f, 100.0f, "fog colour away from the light, linear RGB"},
    {"fog_density", &P::fog_density, nullptr, 0.0f, 1.0f, "fog extinction per metre at fog_height"},
    {"fog_height", &P::fog_height, nullptr, -10000.0f, 10000.0f, "world z where the fog has fog_density, metres"},
    {"fog_height_falloff", &P::fog_height_falloff, nullptr, 0.0f, 10.0f, "exponential decay of fog density per metre of height"},
    {"fog_sun_scatter", &P::fog_sun_scatter, nullptr, 0.0f, 10.0f, "how strongly fog turns light-coloured towards the light"},
    {"cloud_cover", &P::cloud_cover, nullptr, 0.0f, 1.0f, "fraction of the sky covered by clouds"},
    {"cloud_scale", &P::cloud_scale, nullptr, 1.0f, 100000.0f, "size of cloud features on the cloud plane, metres"},
    {"cloud_color", nullptr, &P::cloud_color, 0.0f, 100.0f, "albedo of the clouds, linear RGB"},
    {"star_density", &P::star_density, nullptr, 0.0f, 0.05f, "fraction of sky cells holding a star"},
    {"exposure_ev", &P::exposure_ev, nullptr, -20.0f, 20.0f, "camera exposure in stops: radiance x 2^ev before tone mapping"},
};
}  // namespace

std::span<const PresetField> preset_fields() { return kFields; }

LightingPreset preset_day() { return LightingPreset{}; }

LightingPreset preset_dusk() {
  LightingPreset p = preset_day();
  p.sun_elevation_deg = 6;
  p.sun_azimuth_deg = 200;
  p.sun_color = {1.0f, 0.55f, 0.25f};
  p.sun_intensity = 1.0f;
  p.sun_disc_deg = 0.7f;
  p.sun_disc_intensity = 30;
  p.sky_zenith = {0.08f, 0.12f, 0.3f};
  p.sky_horizon = {0.75f, 0.45f, 0.28f};
  p.sky_intensity = 0.5f;
  p.sun_glow = 1.2f;
  p.ground_color = {0.07f, 0.05f, 0.03f};
  p.ambient_intensity = 0.8f;
  p.foliage_translucency = 0.45f;
  p.fog_color = {0.45f, 0.38f, 0.4f};
  p.fog_density = 0.012f;
  p.fog_height_falloff = 0.1f;
  p.fog_sun_scatter = 0.9f;
  p.cloud_cover = 0.45f;
  p.cloud_color = {1.0f, 0.9f, 0.85f};
  p.exposure_ev = 0.5f;
  return p;
}

LightingPreset preset_night() {
  LightingPreset p = preset_day();
  p.sun_elevation_deg = 40;
  p.sun_azimuth_deg = 60;
  p.sun_color = {0.55f, 0.65f, 1.0f};
  p.sun_intensity = 0.12f;
  p.sun_disc_deg = 1.5f;
  p.sun_disc_intensity = 6;
  p.moon = 1;
  p.sky_zenith = {0.004f, 0.008f, 0.025f};
  p.sky_horizon = {0.015f, 0.025f, 0.05f};
  p.sky_intensity = 1.0f;
  p.sun_glow = 0.15f;
  p.ground_color = {0.01f, 0.01f, 0.015f};
  p.ambient_intensity = 0.8f;
  p.foliage_translucency = 0.2f;
  p.fog_color = {0.02f, 0.03f, 0.05f};
  p.fog_density = 0.01f;
  p.fog_sun_scatter = 0.3f;
  p.cloud_cover = 0.25f;
  p.cloud_color = {0.6f, 0.65f, 0.8f};
  p.star_density = 0.004f;
  p.exposure_ev = 1.5f;
  return p;
}

std::map<std::string, LightingPreset> builtin_presets() {
  return {{"day", preset_day()}, {"dusk", preset_dusk()}, {"night", preset_night()}};
}

Vec3f sun_direction(const LightingPreset& preset) {
  const double deg = 3.14159265358979323846 / 180.0;
  const double el = double(preset.sun_elevation_deg) * deg;
  const double az = double(preset.sun_azimuth_deg) * deg;
  return Vec3f(float(std::cos(el) * std::cos(az)), float(std::cos(el) * std::sin(az)), float(std::sin(el)));
}

}  // namespace silva::render
