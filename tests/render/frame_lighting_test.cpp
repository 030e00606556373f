// Per-frame lighting (render/frame_lighting.hpp) and auto-exposure (render/auto_exposure.hpp):
// draws are seeded per frame, stay in their ranges and leave the selected lighting alone when off;
// the white balance and the metering have known answers; auto-exposure brings a dark and a bright
// preset closer to its target than their fixed exposures do.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/camera_model.hpp"
#include "render/auto_exposure.hpp"
#include "render/frame_lighting.hpp"
#include "render/shade.hpp"
#include "shading_scene.hpp"

namespace silva::render {
namespace {

/// A run lighting with randomisation on, drawing among clear, mist and rain.
RunLighting randomized_run() {
  RunLighting run;
  run.randomize.enabled = true;
  run.randomize.weathers = {"clear", "mist", "rain"};
  run.randomize.weather_weights = {1, 1, 1};
  const auto weathers = builtin_weathers();
  for (const std::string& name : run.randomize.weathers) run.weather_choices.push_back(weathers.at(name));
  return run;
}

/// Whether `v` lies in the [min, max] `range`.
bool within(double v, const std::vector<double>& range) { return v >= range[0] && v <= range[1]; }

TEST(FrameLighting, OffLeavesTheSelectedLightingAsItIs) {
  RunLighting run;
  run.preset = preset_dusk();
  run.weather = "mist";
  run.preset.weather = builtin_weathers().at("mist");
  const FrameLighting f = frame_lighting(run, 7, "random", 3);
  EXPECT_FALSE(f.randomized);
  EXPECT_EQ(f.preset, run.preset);
  EXPECT_EQ(f.weather, "mist");
  EXPECT_EQ(f.white_balance, Vec3f::Ones());
  EXPECT_EQ(f.exposure_compensation_ev, 0.0f);
}

TEST(FrameLighting, DrawsArePerFrameInRangeAndRepeatable) {
  const RunLighting run = randomized_run();
  const LightingRandomizeConfig& r = run.randomize;
  std::set<float> elevations;
  std::set<std::string> weathers;
  for (uint64_t frame = 0; frame < 64; ++frame) {
    const FrameLighting f = frame_lighting(run, 1414213562, "random", frame);
    SCOPED_TRACE(frame);
    EXPECT_TRUE(f.randomized);
    EXPECT_TRUE(within(f.preset.sun_elevation_deg, r.sun_elevation_deg));
    EXPECT_TRUE(within(f.preset.sun_azimuth_deg, r.sun_azimuth_deg));
    EXPECT_TRUE(within(f.preset.cloud_cover, r.cloud_cover));
    EXPECT_TRUE(within(f.fog_density_scale, r.fog_density_scale));
    EXPECT_FLOAT_EQ(f.preset.fog_density, preset_day().fog_density * f.fog_density_scale);
    EXPECT_TRUE(within(f.exposure_compensation_ev, r.exposure_compensation_ev));
    EXPECT_TRUE(within(f.white_balance_k, r.white_balance_k));
    EXPECT_EQ(f.white_balance, white_balance_gains(f.white_balance_k));
    EXPECT_EQ(f.preset.weather, builtin_weathers().at(f.weather));
    const FrameLighting again = frame_lighting(run, 1414213562, "random", frame);
    EXPECT_EQ(again.preset, f.preset);
    EXPECT_EQ(again.weather, f.weather);
    elevations.insert(f.preset.sun_elevation_deg);
    weathers.insert(f.weather);
  }
  EXPECT_EQ(elevations.size(), 64u);  // every frame draws anew
  EXPECT_EQ(weathers.size(), 3u);     // every weather with a weight comes up
  EXPECT_NE(frame_lighting(run, 1, "random", 0).preset, frame_lighting(run, 1, "autopilot", 0).preset);
  EXPECT_NE(frame_lighting(run, 1, "random", 0).preset, frame_lighting(run, 2, "random", 0).preset);
}

TEST(FrameLighting, WeatherWeightsAreFollowedAndZeroIsNeverDrawn) {
  RunLighting run = randomized_run();
  run.randomize.weather_weights = {3, 0, 1};
  int clear = 0, rain = 0;
  for (uint64_t frame = 0; frame < 2000; ++frame) {
    const std::string w = frame_lighting(run, 5, "random", frame).weather;
    ASSERT_NE(w, "mist");
    (w == "clear" ? clear : rain) += 1;
  }
  EXPECT_NEAR(double(clear) / 2000.0, 0.75, 0.04);
  EXPECT_EQ(clear + rain, 2000);
}

TEST(FrameLighting, WhiteBalanceIsNeutralAtD65AndWarmsAbove) {
  const Vec3f neutral = white_balance_gains(FrameLighting::kNeutralWhiteK);
  EXPECT_NEAR(neutral.x(), 1.0f, 1e-6f);
  EXPECT_NEAR(neutral.y(), 1.0f, 1e-6f);
  EXPECT_NEAR(neutral.z(), 1.0f, 1e-6f);
  const Vec3f tungsten = white_balance_gains(3200.0f);  // balanced for warm light: daylight turns blue
  EXPECT_GT(tungsten.z(), 1.5f * tungsten.x());
  const Vec3f shade = white_balance_gains(10000.0f);  // balanced for blue shade: daylight turns warm
  EXPECT_GT(shade.x(), shade.z());
  for (const Vec3f& g : {tungsten, shade})  // unit luminance: white balance does not expose
    EXPECT_NEAR(0.2126f * g.x() + 0.7152f * g.y() + 0.0722f * g.z(), 1.0f, 1e-5f);
}

TEST(AutoExposure, MetersALogAverageAndExposesItToTheKey) {
  LinearFrame frame;
  frame.resize(64, 32);
  for (Vec3f& c : frame.rgb) c = Vec3f::Constant(2.0f);
  EXPECT_NEAR(log_average_luminance(frame), 2.0, 1e-9);
  // Half the metered pixels at 8, half at 0.5: the log-average is their geometric mean, 2.
  for (int v = 0; v < frame.height; ++v)
    for (int u = 0; u < frame.width; ++u)
      frame.rgb[size_t(v) * 64 + size_t(u)] = Vec3f::Constant((u / kMeterStep) % 2 ? 8.0f : 0.5f);
  EXPECT_NEAR(log_average_luminance(frame), 2.0, 1e-9);
  const float ev = ev100_for_luminance(2.0);
  EXPECT_NEAR(2.0 * exposure_multiplier(ev), kAutoExposureKey, 1e-5);
  EXPECT_EQ(ev100_for_luminance(0.0), ev100_for_luminance(kMeterFloor));  // black meters as the floor
  EXPECT_GE(ev100_for_luminance(0.0), kMinEv100);
  EXPECT_EQ(ev100_for_luminance(1e12), kMaxEv100);
}

/// Mean Rec.709 luma of 8-bit sRGB bytes.
double mean_luma(const std::vector<uint8_t>& rgb) {
  double sum = 0;
  for (size_t i = 0; i < rgb.size(); i += 3) sum += 0.2126 * rgb[i] + 0.7152 * rgb[i + 1] + 0.0722 * rgb[i + 2];
  return sum / double(rgb.size() / 3);
}

/// The ground plane and sky under `preset`, exposed by the preset or automatically; `ev100` receives the exposure used.
double shaded_luma(const LightingPreset& preset, bool automatic, float* ev100 = nullptr) {
  const Camera cam = test::test_camera(96, 64, 5);
  const GBuffer g = test::plane_gbuffer(cam, Material::Ground);
  std::vector<uint8_t> rgb;
  const ShadeCounts counts =
      shade_rgb({g, cam, preset, nullptr, 1, "random", 0, camera_model(CameraConfig{}, cam), automatic}, rgb);
  if (ev100) *ev100 = counts.ev100;
  return mean_luma(rgb);
}

TEST(AutoExposure, BringsADarkAndABrightPresetCloserToTheTarget) {
  LightingPreset dark = preset_day(), bright = preset_day();
  dark.ev100 += 3.0f;    // under-exposed by 3 stops
  bright.ev100 -= 3.0f;  // over-exposed by 3 stops
  const double fixed_gap = shaded_luma(bright, false) - shaded_luma(dark, false);
  float ev_dark = 0, ev_bright = 0;
  const double auto_gap = std::abs(shaded_luma(bright, true, &ev_bright) - shaded_luma(dark, true, &ev_dark));
  EXPECT_GT(fixed_gap, 60.0);
  EXPECT_LT(auto_gap, 0.1 * fixed_gap);
  EXPECT_EQ(ev_dark, ev_bright);  // the metering reads the light, not the preset's exposure
  // Night is metered as far below day as its light is: the moon is 2.5e-6 of the sun (18.6 stops) and
  // the night sky 1.5e-6 of the day's (19.3 stops); the auto exposure follows the light.
  float ev_night = 0;
  shaded_luma(preset_night(), true, &ev_night);
  EXPECT_GT(ev_dark - ev_night, 18.3);
  EXPECT_LT(ev_dark - ev_night, 19.8);
  float ev_fixed = 0;
  shaded_luma(preset_day(), false, &ev_fixed);
  EXPECT_EQ(ev_fixed, preset_day().ev100);
}

TEST(AutoExposure, CompensationBrightensEitherMode) {
  const Camera cam = test::test_camera(96, 64, 5);
  const GBuffer g = test::plane_gbuffer(cam, Material::Ground);
  for (const bool automatic : {false, true}) {
    std::vector<uint8_t> plain, brighter;
    const CameraModel model = camera_model(CameraConfig{}, cam);
    const float ev = shade_rgb({g, cam, preset_day(), nullptr, 1, "random", 0, model, automatic, 0.0f}, plain).ev100;
    const float ev_up = shade_rgb({g, cam, preset_day(), nullptr, 1, "random", 0, model, automatic, 1.0f}, brighter).ev100;
    EXPECT_FLOAT_EQ(ev_up, ev - 1.0f) << automatic;
    EXPECT_GT(mean_luma(brighter), mean_luma(plain) + 5.0) << automatic;
  }
}

}  // namespace
}  // namespace silva::render
