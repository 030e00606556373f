#include "render/lighting.hpp"

#include <algorithm>
#include <cmath>

#include "render/post.hpp"

namespace silva::render {

namespace {
using P = LightingPreset;
constexpr PresetField kFields[] = {
    {"sun_elevation_deg", &P::sun_elevation_deg, nullptr, -90.0f, 90.0f, "light elevation above the horizon, degrees"},
    {"sun_azimuth_deg", &P::sun_azimuth_deg, nullptr, -360.0f, 360.0f, "light azimuth, degrees counter-clockwise from world +X"},
    {"turbidity", &P::turbidity, nullptr, 2.0f, 10.0f, "haze of the Preetham sky model: 2 very clear, 3 clear, 6 hazy, 10 thick haze"},
    {"sun_tint", nullptr, &P::sun_tint, 0.0f, 100.0f, "multiplies the sky model's sun colour, linear RGB"},
    {"sun_intensity", &P::sun_intensity, nullptr, 0.0f, 1000.0f, "multiplies the sun's illuminance (1 = the sun, 2.5e-6 = a full moon)"},
    {"sun_disc_deg", &P::sun_disc_deg, nullptr, 0.0f, 20.0f, "angular diameter of the visible sun/moon disc, degrees"},
    {"sky_tint", nullptr, &P::sky_tint, 0.0f, 100.0f, "multiplies the sky model's colour (sky pixels and sky light), linear RGB"},
    {"sky_intensity", &P::sky_intensity, nullptr, 0.0f, 1000.0f, "multiplies the sky model's luminance (sky pixels and sky light)"},
    {"ground_albedo", nullptr, &P::ground_albedo, 0.0f, 1.0f, "albedo of the ground that bounces light up onto surfaces, linear RGB"},
    {"ambient_intensity", &P::ambient_intensity, nullptr, 0.0f, 1000.0f, "multiplies the sky and ground light on surfaces (1 = physical)"},
    {"ao_strength", &P::ao_strength, nullptr, 0.0f, 1.0f, "how much ambient occlusion darkens ambient light"},
    {"foliage_translucency", &P::foliage_translucency, nullptr, 0.0f, 1.0f, "fraction of the light reaching back-lit leaves"},
    {"fog_tint", nullptr, &P::fog_tint, 0.0f, 100.0f, "multiplies the light the fog scatters (sky, ground bounce, sun), linear RGB"},
    {"fog_density", &P::fog_density, nullptr, 0.0f, 1.0f, "fog extinction per metre at fog_height"},
    {"fog_height", &P::fog_height, nullptr, -10000.0f, 10000.0f, "world z where the fog has fog_density, metres"},
    {"fog_height_falloff", &P::fog_height_falloff, nullptr, 0.0f, 10.0f, "exponential decay of fog density per metre of height"},
    {"fog_sun_scatter", &P::fog_sun_scatter, nullptr, 0.0f, 10.0f, "how strongly fog turns light-coloured towards the light"},
    {"cloud_cover", &P::cloud_cover, nullptr, 0.0f, 1.0f, "fraction of the sky covered by clouds (1 = overcast: no direct light)"},
    {"cloud_scale", &P::cloud_scale, nullptr, 1.0f, 100000.0f, "size of cloud features on the cloud plane, metres"},
    {"cloud_color", nullptr, &P::cloud_color, 0.0f, 100.0f, "albedo of the clouds, linear RGB"},
    {"cloud_transmittance", &P::cloud_transmittance, nullptr, 0.0f, 1.0f, "fraction of the clear-sky daylight a full overcast lets through"},
    {"star_density", &P::star_density, nullptr, 0.0f, 0.05f, "fraction of sky cells holding a star"},
    {"ev100", &P::ev100, nullptr, -10.0f, 20.0f, "camera exposure value at ISO 100: open sun 15, forest 13.5, dusk 11.5, moonlight -2 (higher = darker image)"},
};

using W = WeatherPreset;
constexpr WeatherField kWeatherFields[] = {
    {"cloud_cover_min", &W::cloud_cover_min, nullptr, 0.0f, 1.0f, "the sky's cloud cover is at least this (1 = overcast)"},
    {"cloud_transmittance_scale", &W::cloud_transmittance_scale, nullptr, 0.0f, 1.0f, "multiplies the time of day's cloud_transmittance (darker clouds)"},
    {"fog_density_scale", &W::fog_density_scale, nullptr, 0.0f, 1000.0f, "multiplies the time of day's fog_density"},
    {"ev100_offset", &W::ev100_offset, nullptr, -10.0f, 10.0f, "added to the time of day's ev100 (negative = brighter image)"},
    {"wetness", &W::wetness, nullptr, 0.0f, 1.0f, "wet look: darker, more saturated and glossier surfaces"},
    {"snow_cover", &W::snow_cover, nullptr, 0.0f, 1.0f, "snow on upward-facing surfaces and the ground (RGB only)"},
    {"rain_streaks", &W::rain_streaks, nullptr, 0.0f, 1.0f, "density of falling rain streaks drawn over the RGB"},
    {"snowfall", &W::snowfall, nullptr, 0.0f, 1.0f, "density of falling snowflakes drawn over the RGB"},
};
}  // namespace

std::span<const PresetField> preset_fields() { return kFields; }
std::span<const WeatherField> weather_fields() { return kWeatherFields; }

LightingPreset preset_day() { return LightingPreset{}; }

LightingPreset preset_dusk() {
  LightingPreset p = preset_day();
  p.sun_elevation_deg = 6;
  p.sun_azimuth_deg = 200;
  p.turbidity = 5.0f;
  p.sky_tint = {1.0f, 0.9f, 0.78f};
  p.sun_disc_deg = 0.7f;
  p.foliage_translucency = 0.45f;
  p.fog_density = 0.012f;
  p.fog_height_falloff = 0.1f;
  p.fog_sun_scatter = 0.9f;
  p.cloud_cover = 0.45f;
  p.ev100 = 11.5f;
  return p;
}

LightingPreset preset_night() {
  LightingPreset p = preset_day();
  p.sun_elevation_deg = 40;
  p.sun_azimuth_deg = 60;
  p.sun_tint = {0.7f, 0.85f, 1.2f};
  p.sun_intensity = 2.5e-6f;
  p.sun_disc_deg = 1.5f;
  p.sky_tint = {0.45f, 0.7f, 1.5f};
  p.sky_intensity = 1.5e-6f;
  p.foliage_translucency = 0.2f;
  p.fog_density = 0.01f;
  p.fog_sun_scatter = 0.3f;
  p.cloud_cover = 0.25f;
  p.cloud_color = {0.6f, 0.65f, 0.8f};
  p.star_density = 0.004f;
  p.ev100 = -2.0f;
  return p;
}

std::map<std::string, LightingPreset> builtin_presets() {
  return {{"day", preset_day()}, {"dusk", preset_dusk()}, {"night", preset_night()}};
}

std::map<std::string, WeatherPreset> builtin_weathers() {
  WeatherPreset overcast;
  overcast.cloud_cover_min = 1.0f;
  overcast.fog_density_scale = 1.5f;
  overcast.ev100_offset = -1.0f;
  WeatherPreset mist;
  mist.cloud_cover_min = 0.7f;
  mist.fog_density_scale = 6.0f;
  WeatherPreset rain;
  rain.cloud_cover_min = 1.0f;
  rain.cloud_transmittance_scale = 0.6f;
  rain.fog_density_scale = 3.0f;
  rain.ev100_offset = -1.5f;
  rain.wetness = 1.0f;
  rain.rain_streaks = 0.5f;
  WeatherPreset snow;
  snow.cloud_cover_min = 0.9f;
  snow.fog_density_scale = 2.0f;
  snow.ev100_offset = -0.5f;
  snow.snow_cover = 0.85f;
  snow.snowfall = 0.4f;
  return {{"clear", WeatherPreset{}}, {"overcast", overcast}, {"mist", mist}, {"rain", rain}, {"snow", snow}};
}

LightingPreset with_weather(const LightingPreset& preset) {
  LightingPreset p = preset;
  p.cloud_cover = std::max(p.cloud_cover, p.weather.cloud_cover_min);
  p.cloud_transmittance *= p.weather.cloud_transmittance_scale;
  p.fog_density = std::min(p.fog_density * p.weather.fog_density_scale, 1.0f);
  p.ev100 += p.weather.ev100_offset;
  return p;
}

float exposure_multiplier(float ev100) {
  constexpr double kHeadroom = 2.0, kSaturation = 1.2, kCdPerUnit = 1000.0;  // radiance unit: kcd/m²
  return float(kHeadroom * kCdPerUnit / kSaturation) * exposure_scale(-ev100);
}

Vec3f sun_direction(const LightingPreset& preset) {
  const double deg = 3.14159265358979323846 / 180.0;
  const double el = double(preset.sun_elevation_deg) * deg;
  const double az = double(preset.sun_azimuth_deg) * deg;
  return Vec3f(float(std::cos(el) * std::cos(az)), float(std::cos(el) * std::sin(az)), float(std::sin(el)));
}

}  // namespace silva::render
