#include <gtest/gtest.h>

#include <string>

#include "app/config/lighting_config.hpp"
#include "core/error.hpp"

namespace silva::app {
namespace {

using render::LightingPreset;

/// The InputError message of parsing `text`, or "" if it parsed.
std::string error_of(const std::string& text) {
  try {
    parse_lighting_presets(toml::parse(text), "user.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(LightingConfig, ShippedFileEqualsTheBuiltins) {
  const auto parsed = load_lighting_presets(std::string(SILVA_SOURCE_DIR) + "/configs/lighting.toml");
  EXPECT_EQ(parsed, render::builtin_presets());
}

TEST(LightingConfig, ShippedFileSpellsOutEveryFieldOfEveryPreset) {
  const toml::table root = toml::parse_file(std::string(SILVA_SOURCE_DIR) + "/configs/lighting.toml");
  for (const char* name : {"day", "dusk", "night"}) {
    const toml::table* t = root["lighting"]["presets"][name].as_table();
    ASSERT_NE(t, nullptr) << name;
    EXPECT_EQ(t->size(), render::preset_fields().size()) << name;
    for (const render::PresetField& f : render::preset_fields()) EXPECT_TRUE(t->contains(f.name)) << name << "." << f.name;
  }
}

TEST(LightingConfig, FieldsAreOptionalAndNewNamesStartFromDay) {
  const auto presets = parse_lighting_presets(toml::parse(R"(
    [lighting.presets.dusk]
    sun_intensity = 2
    [lighting.presets.foggy]
    fog_density = 0.05
    fog_color = [0.5, 0.5, 0.5]
  )"),
                                              "user.toml");
  LightingPreset dusk = render::preset_dusk();
  dusk.sun_intensity = 2.0f;
  EXPECT_EQ(presets.at("dusk"), dusk);
  LightingPreset foggy = render::preset_day();
  foggy.fog_density = 0.05f;
  foggy.fog_color = {0.5f, 0.5f, 0.5f};
  EXPECT_EQ(presets.at("foggy"), foggy);
  EXPECT_EQ(presets.at("night"), render::preset_night());
  EXPECT_EQ(parse_lighting_presets(toml::table{}, "empty.toml"), render::builtin_presets());
}

TEST(LightingConfig, UnknownKeyNamesTheKeyAndListsTheAllowedOnes) {
  const std::string msg = error_of("[lighting.presets.day]\nsun_brightness = 3\n");
  EXPECT_NE(msg.find("user.toml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("lighting.presets.day.sun_brightness"), std::string::npos) << msg;
  EXPECT_NE(msg.find("sun_intensity"), std::string::npos) << msg;
  EXPECT_NE(msg.find("exposure_ev"), std::string::npos) << msg;
}

TEST(LightingConfig, WrongTypeNamesTheKeyAndTheExpectedType) {
  const std::string scalar = error_of("[lighting.presets.night]\nsun_intensity = \"bright\"\n");
  EXPECT_NE(scalar.find("lighting.presets.night.sun_intensity"), std::string::npos) << scalar;
  EXPECT_NE(scalar.find("a number"), std::string::npos) << scalar;
  const std::string colour = error_of("[lighting.presets.day]\nsky_zenith = [0.1, 0.2]\n");
  EXPECT_NE(colour.find("lighting.presets.day.sky_zenith"), std::string::npos) << colour;
  EXPECT_NE(colour.find("3 numbers"), std::string::npos) << colour;
  const std::string not_table = error_of("[lighting.presets]\nday = 3\n");
  EXPECT_NE(not_table.find("lighting.presets.day"), std::string::npos) << not_table;
}

TEST(LightingConfig, OutOfRangeValueIsRejected) {
  const std::string msg = error_of("[lighting.presets.day]\ncloud_cover = 1.5\n");
  EXPECT_NE(msg.find("lighting.presets.day.cloud_cover"), std::string::npos) << msg;
  EXPECT_NE(msg.find("out of range"), std::string::npos) << msg;
  EXPECT_EQ(error_of("[lighting.presets.day]\ncloud_cover = 1\n"), "");  // integers are numbers
}

TEST(LightingConfig, MissingFileIsAnIoError) {
  EXPECT_THROW(load_lighting_presets("/nonexistent/lighting.toml"), IoError);
}

}  // namespace
}  // namespace silva::app
