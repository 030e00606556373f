#include "pipeline/config/config_print.hpp"

#include <gtest/gtest.h>

#include "tests/common/config_equal.hpp"

namespace silva::pipeline {
namespace {

using testing::config_differences;

LoadedConfig unusual_config() {
  ConfigSources sources;
  sources.overrides = {"seed=9999999999", "camera.near=0.1", "camera.fov_deg=33.3333333333333",
                       "output.dir=\"we\\\"ird \\\\ dir\"", "output.types=[]",
                       "captures.autopilot_yaws=[-45.125, 0, 1e-3]", "captures.sequences=[\"random\"]",
                       "render.lod=false", "terrain.octaves=9", "output.resolution=17x8192"};
  return load_config(sources);
}

TEST(ConfigPrint, TomlRoundTripsDefaults) {
  LoadedConfig loaded;
  loaded.config.seed = 1234567890;
  const LoadedConfig again = parse_config_text(config_to_toml(loaded), "printed");
  EXPECT_EQ(config_differences(again.config, loaded.config), "");
  EXPECT_TRUE(again.seed_given);
}

TEST(ConfigPrint, TomlRoundTripsEveryValue) {
  const LoadedConfig loaded = unusual_config();
  EXPECT_EQ(loaded.config.output.dir, "we\"ird \\ dir");
  const std::string text = config_to_toml(loaded);
  const LoadedConfig again = parse_config_text(text, "printed");
  EXPECT_EQ(config_differences(again.config, loaded.config), "") << text;
}

TEST(ConfigPrint, TomlHasEveryKeyAndUserPresets) {
  const LoadedConfig loaded = parse_config_text(
      "[lighting]\ntime_of_day = \"my noon\"\n[lighting.presets.\"my noon\"]\n"
      "sun_tint = [0.5, 1, 0.25]\nfog_density = 0.02\n"
      "[lighting.weather_presets.drizzle]\nwetness = 0.4\nrain_streaks = 0.1\n",
      "a.toml");
  const std::string text = config_to_toml(loaded);
  for (const ConfigKey& key : config_schema()) {
    EXPECT_NE(text.find(std::string("\n").append(key.leaf()).append(" = ")), std::string::npos) << key.name;
  }
  const LoadedConfig again = parse_config_text(text, "printed");
  EXPECT_EQ(again.config.lighting.time_of_day, "my noon");
  EXPECT_EQ(again.lighting_presets, loaded.lighting_presets) << text;
  EXPECT_EQ(again.weather_presets, loaded.weather_presets) << text;
  EXPECT_FALSE(again.weather_presets.empty());
}

TEST(ConfigPrint, JsonIsNestedBySection) {
  const LoadedConfig loaded = unusual_config();
  const nlohmann::json json = config_to_json(loaded);
  EXPECT_EQ(json["seed"], 9999999999);
  EXPECT_EQ(json["output"]["resolution"], "17x8192");
  EXPECT_EQ(json["camera"]["near"], 0.1);
  EXPECT_EQ(json["render"]["lod"], false);
  EXPECT_EQ(json["captures"]["sequences"], nlohmann::json::array({"random"}));
  EXPECT_EQ(json.size(), 13u);  // seed + 12 sections
}

TEST(ConfigPrint, QuotesStrings) {
  EXPECT_EQ(toml_quote("a\"b\\c\n"), "\"a\\\"b\\\\c\\n\"");
}

}  // namespace
}  // namespace silva::pipeline
