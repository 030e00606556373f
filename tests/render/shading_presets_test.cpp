#include <gtest/gtest.h>

#include "core/camera_model.hpp"
#include "render/lighting.hpp"
#include "render/shade.hpp"
#include "shading_scene.hpp"

namespace silva::render {
namespace {

/// Mean Rec.709 luma of 8-bit sRGB bytes (a brightness order is all the test needs).
double mean_luma(const std::vector<uint8_t>& rgb) {
  double sum = 0;
  for (size_t i = 0; i < rgb.size(); i += 3) sum += 0.2126 * rgb[i] + 0.7152 * rgb[i + 1] + 0.0722 * rgb[i + 2];
  return sum / double(rgb.size() / 3);
}

std::vector<uint8_t> shade_view(const LightingPreset& preset) {
  const Camera cam = test::test_camera(96, 64, 5);
  const GBuffer g = test::plane_gbuffer(cam, Material::Ground);
  std::vector<uint8_t> rgb;
  shade_rgb({g, cam, preset, nullptr, 1, "random", 0, camera_model(CameraConfig{}, cam)}, rgb);
  return rgb;
}

TEST(ShadingPresets, NightDarkerThanDuskDarkerThanDay) {
  const double day = mean_luma(shade_view(preset_day()));
  const double dusk = mean_luma(shade_view(preset_dusk()));
  const double night = mean_luma(shade_view(preset_night()));
  EXPECT_LT(night, dusk);
  EXPECT_LT(dusk, day);
  EXPECT_GT(night, 1.0);  // night is dark, not black
}

TEST(ShadingPresets, BuiltinsAreNamedAndDistinct) {
  const auto presets = builtin_presets();
  ASSERT_EQ(presets.size(), 3u);
  EXPECT_EQ(presets.at("day"), preset_day());
  EXPECT_EQ(presets.at("day"), LightingPreset{});
  EXPECT_NE(presets.at("dusk"), presets.at("day"));
  EXPECT_NE(presets.at("night"), presets.at("dusk"));
  EXPECT_EQ(preset_night().moon, 1.0f);
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

TEST(ShadingPresets, EveryFieldIsListedOnceWithItsRangeHoldingTheBuiltins) {
  const auto fields = preset_fields();
  EXPECT_EQ(fields.size(), 25u);
  for (const auto& [name, p] : builtin_presets()) {
    for (const PresetField& f : fields) {
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

}  // namespace
}  // namespace silva::render
