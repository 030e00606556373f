#include <gtest/gtest.h>

#include "core/camera_model.hpp"
#include "render/lighting.hpp"
#include "render/shade.hpp"
#include "render/weather_overlay.hpp"
#include "shading_scene.hpp"

namespace silva::render {
namespace {

/// Mean Rec.709 luma of 8-bit sRGB bytes (a brightness order is all the test needs).
double mean_luma(const std::vector<uint8_t>& rgb) {
  double sum = 0;
  for (size_t i = 0; i < rgb.size(); i += 3) sum += 0.2126 * rgb[i] + 0.7152 * rgb[i + 1] + 0.0722 * rgb[i + 2];
  return sum / double(rgb.size() / 3);
}

std::vector<uint8_t> shade_view(const LightingPreset& preset, double pitch_deg = 5) {
  const Camera cam = test::test_camera(96, 64, pitch_deg);
  const GBuffer g = test::plane_gbuffer(cam, Material::Ground);
  std::vector<uint8_t> rgb;
  shade_rgb({g, cam, preset, nullptr, 1, "random", 0, camera_model(CameraConfig{}, cam)}, rgb);
  return rgb;
}

TEST(ShadingPresets, NightDarkerThanDuskDarkerThanDay) {
  for (const double pitch : {-20.0, 5.0, 60.0}) {  // pitched down: much sky, little sky, ground only
    const double day = mean_luma(shade_view(preset_day(), pitch));
    const double dusk = mean_luma(shade_view(preset_dusk(), pitch));
    const double night = mean_luma(shade_view(preset_night(), pitch));
    EXPECT_LT(night, dusk) << pitch;
    EXPECT_LT(dusk, day) << pitch;
    EXPECT_GT(night, 1.0) << pitch;  // night is dark, not black
  }
}

TEST(ShadingPresets, HigherEv100IsADarkerImage) {
  LightingPreset bright = preset_day(), dark = preset_day();
  dark.ev100 += 2.0f;
  EXPECT_LT(mean_luma(shade_view(dark)), mean_luma(shade_view(bright)));
  EXPECT_FLOAT_EQ(exposure_multiplier(15.0f) * 4.0f, exposure_multiplier(13.0f));
  // 2 / (1.2 · 2^EV100) per cd/m², radiance in kcd/m²: EV100 0 gives 2000 / 1.2.
  EXPECT_FLOAT_EQ(exposure_multiplier(0.0f), 2000.0f / 1.2f);
}

TEST(ShadingPresets, BuiltinsAreNamedAndDistinct) {
  const auto presets = builtin_presets();
  ASSERT_EQ(presets.size(), 3u);
  EXPECT_EQ(presets.at("day"), preset_day());
  EXPECT_EQ(presets.at("day"), LightingPreset{});
  EXPECT_NE(presets.at("dusk"), presets.at("day"));
  EXPECT_NE(presets.at("night"), presets.at("dusk"));
  EXPECT_GT(preset_day().ev100, preset_dusk().ev100);  // less light, more exposure
  EXPECT_GT(preset_dusk().ev100, preset_night().ev100);
  const auto weathers = builtin_weathers();
  ASSERT_EQ(weathers.size(), 5u);
  EXPECT_EQ(weathers.at("clear"), WeatherPreset{});
  for (const char* name : {"overcast", "mist", "rain", "snow"}) EXPECT_NE(weathers.at(name), WeatherPreset{}) << name;
}

TEST(ShadingPresets, WeatherRaisesCloudsAndFogAndShiftsExposure) {
  LightingPreset p = preset_day();
  p.weather = builtin_weathers().at("rain");
  const LightingPreset lit = with_weather(p);
  EXPECT_EQ(lit.cloud_cover, 1.0f);
  EXPECT_FLOAT_EQ(lit.fog_density, preset_day().fog_density * p.weather.fog_density_scale);
  EXPECT_FLOAT_EQ(lit.ev100, preset_day().ev100 + p.weather.ev100_offset);
  EXPECT_FLOAT_EQ(lit.cloud_transmittance, preset_day().cloud_transmittance * p.weather.cloud_transmittance_scale);
  EXPECT_EQ(with_weather(preset_dusk()), preset_dusk());  // clear changes nothing
}

TEST(ShadingPresets, OvercastHasNoSunShading) {
  // Under an overcast the sunlit and shadowed ground look alike: the plane is evenly lit.
  LightingPreset overcast = preset_day();
  overcast.weather = builtin_weathers().at("overcast");
  const Camera cam = test::test_camera(64, 48, 60);
  const GBuffer g = test::plane_gbuffer(cam, Material::Ground);
  const Vec3d to_sun = sun_direction(overcast).cast<double>();
  const ShadowMap shadow = test::plane_shadow_map(to_sun, 256, 0.1, 4.0, 3.0);
  std::vector<uint8_t> lit, unshadowed;
  shade_rgb({g, cam, overcast, &shadow, 1, "random", 0, {}}, lit);
  shade_rgb({g, cam, overcast, nullptr, 1, "random", 0, {}}, unshadowed);
  EXPECT_EQ(lit, unshadowed);
}

TEST(ShadingPresets, SnowAndWetnessChangeTheGroundsLook) {
  LightingPreset snow = preset_day(), rain = preset_day();
  snow.weather.snow_cover = 1.0f;
  rain.weather.wetness = 1.0f;
  const double dry = mean_luma(shade_view(preset_day(), 60));
  EXPECT_GT(mean_luma(shade_view(snow, 60)), dry + 30.0);  // white ground
  EXPECT_LT(mean_luma(shade_view(rain, 60)), dry);         // darker wet ground
}

TEST(ShadingPresets, RainAndSnowfallAreSeededPerFrame) {
  const Sky sky(preset_day());
  const auto draw = [&](const WeatherPreset& weather, uint64_t frame_key, float canopy = 0.0f) {
    const WeatherOverlay overlay(weather, sky, 1, frame_key, 90, canopy);
    std::vector<Vec3f> image(160 * 90, Vec3f::Zero());
    for (int v = 0; v < 90; ++v) overlay.apply_row(v, &image[size_t(v) * 160], 160);
    return image;
  };
  const WeatherPreset rain = builtin_weathers().at("rain"), snow = builtin_weathers().at("snow");
  for (const WeatherPreset& w : {rain, snow}) {
    const std::vector<Vec3f> a = draw(w, 7), b = draw(w, 7), c = draw(w, 8);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
    size_t touched = 0;
    for (const Vec3f& p : a) touched += p != Vec3f::Zero() ? 1 : 0;
    EXPECT_GT(touched, a.size() / 100);  // visible ...
    EXPECT_LT(touched, a.size() / 3);    // ... but the scene stays visible
    // Under a closed canopy about kUnderCanopyFall of the drops and flakes reach the lens.
    size_t sheltered = 0;
    for (const Vec3f& p : draw(w, 7, 1.0f)) sheltered += p != Vec3f::Zero() ? 1 : 0;
    EXPECT_GT(sheltered, 0u);
    EXPECT_LT(double(sheltered), 0.45 * double(touched));
  }
  EXPECT_FALSE(WeatherOverlay(WeatherPreset{}, sky, 1, 7, 90).active());
}

TEST(ShadingPresets, SunDirectionFollowsElevationAndAzimuth) {
  LightingPreset p;
  p.sun_elevation_deg = 90;
  EXPECT_NEAR(sun_direction(p).z(), 1.0f, 1e-6f);
  p.sun_elevation_deg = 0;
  p.sun_azimuth_deg = 90;  // counter-clockwise from +X: +Y
  const Vec3f d = sun_direction(p);
  EXPECT_NEAR(d.x(), 0.0f, 1e-6f);
  EXPECT_NEAR(d.y(), 1.0f, 1e-6f);
  EXPECT_NEAR(d.z(), 0.0f, 1e-6f);
  p.sun_elevation_deg = 30;
  p.sun_azimuth_deg = 0;
  EXPECT_NEAR(sun_direction(p).z(), 0.5f, 1e-6f);
  EXPECT_NEAR(sun_direction(p).norm(), 1.0f, 1e-6f);
}

/// Every field of a preset of type T is listed once, is a scalar or a colour, and holds the built-ins.
template <class T>
void expect_fields_hold(std::span<const PresetFieldOf<T>> fields, const std::map<std::string, T>& builtins) {
  for (const auto& [name, p] : builtins) {
    for (const PresetFieldOf<T>& f : fields) {
      ASSERT_TRUE((f.scalar == nullptr) != (f.colour == nullptr)) << f.name;
      if (f.scalar) {
        EXPECT_GE(p.*f.scalar, f.min) << name << "." << f.name;
        EXPECT_LE(p.*f.scalar, f.max) << name << "." << f.name;
      } else {
        for (float c : p.*f.colour) EXPECT_TRUE(c >= f.min && c <= f.max) << name << "." << f.name;
      }
    }
  }
}

TEST(ShadingPresets, EveryFieldIsListedOnceWithItsRangeHoldingTheBuiltins) {
  EXPECT_EQ(preset_fields().size(), 23u);
  EXPECT_EQ(weather_fields().size(), 8u);
  expect_fields_hold(preset_fields(), builtin_presets());
  expect_fields_hold(weather_fields(), builtin_weathers());
}

}  // namespace
}  // namespace silva::render
