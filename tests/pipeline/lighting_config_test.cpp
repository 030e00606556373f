#include <gtest/gtest.h>

#include <string>

#include "pipeline/config/lighting_config.hpp"
#include "core/error.hpp"

namespace silva::pipeline {
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
  const auto weathers = load_lighting_weathers(std::string(SILVA_SOURCE_DIR) + "/configs/lighting.toml");
  EXPECT_EQ(weathers, render::builtin_weathers());
}

TEST(LightingConfig, ShippedFileSpellsOutEveryFieldOfEveryWeather) {
  const toml::table root = toml::parse_file(std::string(SILVA_SOURCE_DIR) + "/configs/lighting.toml");
  for (const char* name : {"clear", "overcast", "mist", "rain", "snow"}) {
    const toml::table* t = root["lighting"]["weather_presets"][name].as_table();
    ASSERT_NE(t, nullptr) << name;
    EXPECT_EQ(t->size(), render::weather_fields().size()) << name;
    for (const render::WeatherField& f : render::weather_fields()) EXPECT_TRUE(t->contains(f.name)) << name << "." << f.name;
  }
}

TEST(LightingConfig, WeatherFieldsAreOptionalAndNewNamesStartFromClear) {
  const auto weathers = parse_lighting_weathers(toml::parse(R"(
    [lighting.weather_presets.rain]
    rain_streaks = 0.9
    [lighting.weather_presets.drizzle]
    wetness = 0.4
  )"),
                                                "user.toml");
  render::WeatherPreset rain = render::builtin_weathers().at("rain");
  rain.rain_streaks = 0.9f;
  EXPECT_EQ(weathers.at("rain"), rain);
  render::WeatherPreset drizzle;
  drizzle.wetness = 0.4f;
  EXPECT_EQ(weathers.at("drizzle"), drizzle);
  EXPECT_EQ(weathers.at("snow"), render::builtin_weathers().at("snow"));
}

TEST(LightingConfig, BadWeatherFieldsNameTheKey) {
  const auto error = [](const std::string& text) -> std::string {
    try {
      parse_lighting_weathers(toml::parse(text), "user.toml");
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  const std::string unknown = error("[lighting.weather_presets.rain]\nhail = 1\n");
  EXPECT_NE(unknown.find("lighting.weather_presets.rain.hail"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("snowfall"), std::string::npos) << unknown;
  const std::string range = error("[lighting.weather_presets.snow]\nsnow_cover = 2\n");
  EXPECT_NE(range.find("lighting.weather_presets.snow.snow_cover = 2 is out of range, allowed 0 .. 1"), std::string::npos)
      << range;
  EXPECT_EQ(error("[lighting.weather_presets.snow]\nsnow_cover = 1\n"), "");
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
    fog_tint = [0.5, 0.5, 0.5]
  )"),
                                              "user.toml");
  LightingPreset dusk = render::preset_dusk();
  dusk.sun_intensity = 2.0f;
  EXPECT_EQ(presets.at("dusk"), dusk);
  LightingPreset foggy = render::preset_day();
  foggy.fog_density = 0.05f;
  foggy.fog_tint = {0.5f, 0.5f, 0.5f};
  EXPECT_EQ(presets.at("foggy"), foggy);
  EXPECT_EQ(presets.at("night"), render::preset_night());
  EXPECT_EQ(parse_lighting_presets(toml::table{}, "empty.toml"), render::builtin_presets());
}

TEST(LightingConfig, UnknownKeyNamesTheKeyAndListsTheAllowedOnes) {
  const std::string msg = error_of("[lighting.presets.day]\nsun_brightness = 3\n");
  EXPECT_NE(msg.find("user.toml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("lighting.presets.day.sun_brightness"), std::string::npos) << msg;
  EXPECT_NE(msg.find("sun_intensity"), std::string::npos) << msg;
  EXPECT_NE(msg.find("ev100"), std::string::npos) << msg;
}

TEST(LightingConfig, WrongTypeNamesTheKeyAndTheExpectedType) {
  const std::string scalar = error_of("[lighting.presets.night]\nsun_intensity = \"bright\"\n");
  EXPECT_NE(scalar.find("lighting.presets.night.sun_intensity"), std::string::npos) << scalar;
  EXPECT_NE(scalar.find("a number"), std::string::npos) << scalar;
  const std::string colour = error_of("[lighting.presets.day]\nsky_tint = [0.1, 0.2]\n");
  EXPECT_NE(colour.find("lighting.presets.day.sky_tint"), std::string::npos) << colour;
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

TEST(LightingConfig, MissingFileOrFolderIsBadInput) {
  // A data file that is missing or not a regular file is bad input (exit 2), like any input file.
  EXPECT_THROW(load_lighting_presets("/nonexistent/lighting.toml"), InputError);
  EXPECT_THROW(load_lighting_presets("/tmp"), InputError);
}

}  // namespace
}  // namespace silva::pipeline
