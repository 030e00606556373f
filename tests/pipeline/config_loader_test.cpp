#include "pipeline/config/config_checks.hpp"
#include "pipeline/config/config_loader.hpp"

#include <gtest/gtest.h>

#include "tests/common/config_equal.hpp"
#include "core/error.hpp"

namespace silva::pipeline {
namespace {

using testing::config_differences;

/// The InputError message of `f`, or "" when it does not throw one.
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

LoadedConfig with_sets(std::vector<std::string> sets) {
  ConfigSources sources;
  sources.overrides = std::move(sets);
  return load_config(sources);
}

TEST(ConfigLoader, DefaultTomlEqualsBuiltInDefaults) {
  const LoadedConfig loaded = read_config_file(SILVA_SOURCE_DIR "/configs/default.toml");
  EXPECT_EQ(config_differences(loaded.config, Config{}), "");
  EXPECT_FALSE(loaded.seed_given);  // the seed is drawn from the clock
  EXPECT_NO_THROW(load_config({SILVA_SOURCE_DIR "/configs/default.toml", {}, {}, {}}));
}

TEST(ConfigLoader, DefaultsAreTheThesisDefaults) {
  const Config c;
  EXPECT_EQ(c.vegetation.density, 5);
  EXPECT_EQ(c.terrain.max_elevation, 1.5);
  EXPECT_EQ(c.terrain.lacunarity, 2.0);
  EXPECT_EQ(c.terrain.persistence, 0.5);
  EXPECT_EQ(c.output.width, 1920);
  EXPECT_EQ(c.output.height, 1080);
  EXPECT_EQ(c.captures.random_count, 100);
  EXPECT_EQ(c.captures.autopilot_points, 230);
  EXPECT_EQ(c.lighting.time_of_day, "day");
  EXPECT_TRUE(c.trail.enabled);
  EXPECT_FALSE(c.captures.aerial);
  EXPECT_EQ(c.camera.fov_deg, 90);
  EXPECT_EQ(c.camera.near, 0.05);
  EXPECT_EQ(c.camera.far, 150);
}

TEST(ConfigLoader, DemoConfigIsValid) {
  const LoadedConfig demo = load_config({SILVA_SOURCE_DIR "/configs/demo.toml", {}, {}, {}});
  EXPECT_EQ(demo.config.seed, 1234567890);
  EXPECT_EQ(demo.config.output.width, 1280);
  EXPECT_EQ(demo.config.output.types.size(), 8u);
  const size_t captures = size_t(demo.config.captures.autopilot_points) *
                              demo.config.captures.autopilot_yaws.size() +
                          size_t(demo.config.captures.random_count);
  EXPECT_EQ(captures, 30u);
}

TEST(ConfigLoader, SetOverridesEveryType) {
  const LoadedConfig loaded = with_sets({
      "seed=0000000042", "captures.random_count=7", "camera.fov_deg=75", "camera.near=1",
      "vegetation.ground=false", "lighting.time_of_day=dusk", "output.dir=\"my out\"",
      "output.resolution=640x480", "output.types=[\"rgb\", \"depth_preview\"]",
      "captures.autopilot_yaws=[-30, 0.5]", "captures.sequences=['random']"});
  const Config& c = loaded.config;
  EXPECT_TRUE(loaded.seed_given);
  EXPECT_EQ(c.seed, 42);
  EXPECT_EQ(c.captures.random_count, 7);
  EXPECT_EQ(c.camera.fov_deg, 75.0);
  EXPECT_EQ(c.camera.near, 1.0);
  EXPECT_FALSE(c.vegetation.ground);
  EXPECT_EQ(c.lighting.time_of_day, "dusk");
  EXPECT_EQ(c.output.dir, "my out");
  EXPECT_EQ(c.output.width, 640);
  EXPECT_EQ(c.output.height, 480);
  EXPECT_EQ(c.output.types, (std::vector<std::string>{"rgb", "depth_preview"}));
  EXPECT_EQ(c.captures.autopilot_yaws, (std::vector<double>{-30, 0.5}));
  EXPECT_EQ(c.captures.sequences, (std::vector<std::string>{"random"}));
}

TEST(ConfigLoader, LaterSourcesWin) {
  ConfigSources sources{SILVA_SOURCE_DIR "/configs/demo.toml", {"seed=5", "seed=6"}, "7", "elsewhere"};
  const LoadedConfig loaded = load_config(sources);
  EXPECT_EQ(loaded.config.seed, 7);
  EXPECT_EQ(loaded.config.output.dir, "elsewhere");
  EXPECT_EQ(loaded.config.output.width, 1280);  // from the file
}

TEST(ConfigLoader, BadSetValuesNameKeyAndAllowed) {
  EXPECT_EQ(input_error([] { with_sets({"camera.fov_deg"}); }),
            "--set camera.fov_deg: expected key=value, e.g. --set camera.fov_deg=75");
  EXPECT_EQ(input_error([] { with_sets({"camera.fovdeg=75"}); }),
            "--set camera.fovdeg=75: unknown key 'camera.fovdeg' (did you mean 'camera.fov_deg'?)");
  EXPECT_EQ(input_error([] { with_sets({"camera.fov_deg=wide"}); }),
            "--set camera.fov_deg=wide: camera.fov_deg must be a number, got 'wide'");
  EXPECT_EQ(input_error([] { with_sets({"camera.fov_deg=200"}); }),
            "--set camera.fov_deg=200: camera.fov_deg = 200 is out of range (allowed: 10 to 170)");
  EXPECT_EQ(input_error([] { with_sets({"terrain.octaves=2.5"}); }),
            "--set terrain.octaves=2.5: terrain.octaves must be an integer, got a float (2.5)");
  EXPECT_EQ(input_error([] { with_sets({"render.lod=1"}); }),
            "--set render.lod=1: render.lod must be a boolean (true or false), got an integer (1)");
  EXPECT_EQ(input_error([] { with_sets({"output.resolution=8x8"}); }),
            "--set output.resolution=8x8: output.resolution = \"8x8\" is out of range (allowed: "
            "\"WxH\", each 16 to 8192)");
  EXPECT_EQ(input_error([] { with_sets({"output.resolution=big"}); }),
            "--set output.resolution=big: output.resolution must be \"WxH\" (e.g. \"1920x1080\"), "
            "got a string (\"big\")");
  EXPECT_EQ(input_error([] { with_sets({"output.types=[\"rgbb\"]"}); }),
            "--set output.types=[\"rgbb\"]: output.types: \"rgbb\" is not allowed (a subset of rgb, "
            "semantic, semantic_color, instance, depth, depth_exr, normal, depth_preview, lidar; did you "
            "mean \"rgb\"?)");
  EXPECT_EQ(input_error([] { with_sets({"output.types=[\"rgb\",\"rgb\"]"}); }),
            "--set output.types=[\"rgb\",\"rgb\"]: output.types lists \"rgb\" twice");
  EXPECT_EQ(input_error([] { with_sets({"seed=10000000000"}); }),
            "--set seed=10000000000: seed = 10000000000 is out of range (allowed: 0 to 9999999999)");
}

TEST(ConfigLoader, SeedFlagTakesPrintedSeeds) {
  EXPECT_EQ(load_config({"", {}, "0000000042", {}}).config.seed, 42);
  EXPECT_EQ(input_error([] { load_config({"", {}, "-1", {}}); }),
            "--seed -1: seed = -1 is out of range (allowed: 0 to 9999999999)");
  EXPECT_EQ(input_error([] { load_config({"", {}, "abc", {}}); }),
            "--seed abc: seed must be an integer, got 'abc'");
}

TEST(ConfigLoader, FileErrorsNameFileLineAndKey) {
  EXPECT_EQ(input_error([] { read_config_file("/nonexistent/silva.toml"); }),
            "config file '/nonexistent/silva.toml' not found");
  EXPECT_EQ(input_error([] { parse_config_text("[camera]\nfov_deg = \"wide\"\n", "a.toml"); }),
            "a.toml:2:11: camera.fov_deg must be a number, got a string (\"wide\")");
  EXPECT_EQ(input_error([] { parse_config_text("[camera]\nfovdeg = 75\n", "a.toml"); }),
            "a.toml:2:10: unknown key 'camera.fovdeg' (did you mean 'camera.fov_deg'?)");
  EXPECT_EQ(input_error([] { parse_config_text("[camra]\nnear = 1\n", "a.toml"); }),
            "a.toml:2:8: unknown key 'camra.near' (did you mean 'camera.near'?)");
  EXPECT_EQ(input_error([] { parse_config_text("camera = 5\n", "a.toml"); }),
            "a.toml:1:10: 'camera' must be a table of keys [camera], got an integer (5)");
  const std::string syntax = input_error([] { parse_config_text("[camera\nfov_deg = 75\n", "a.toml"); });
  EXPECT_EQ(syntax.rfind("a.toml:1:", 0), 0u) << syntax;
  EXPECT_NE(syntax.find("invalid TOML"), std::string::npos) << syntax;
  EXPECT_EQ(syntax.find('\n'), std::string::npos);
}

TEST(ConfigLoader, KeepsUserLightingPresets) {
  const LoadedConfig loaded = parse_config_text(
      "[lighting]\ntime_of_day = \"noon\"\n[lighting.presets.noon]\nsun_elevation_deg = 80.0\n",
      "a.toml");
  EXPECT_EQ(loaded.config.lighting.time_of_day, "noon");
  EXPECT_EQ(lighting_preset_names(loaded), (std::vector<std::string>{"day", "dusk", "night", "noon"}));
  EXPECT_EQ(input_error([] { parse_config_text("[lighting.presets]\nnoon = 3\n", "a.toml"); }),
            "a.toml:2:8: lighting.presets.noon must be a table [lighting.presets.noon], got an integer (3)");
  EXPECT_NE(input_error([] { parse_config_text("[lighting.presets.noon]\nsun_elevation_deg = 500\n", "a.toml"); }), "");
}

TEST(ConfigLoader, ClockSeedIsTenDigitsAndOnlyWhenAbsent) {
  LoadedConfig drawn;
  resolve_seed(drawn);
  EXPECT_TRUE(drawn.seed_from_clock);
  EXPECT_GE(drawn.config.seed, 0);
  EXPECT_LE(drawn.config.seed, 9999999999);
  LoadedConfig given = load_config({"", {}, "17", {}});
  resolve_seed(given);
  EXPECT_FALSE(given.seed_from_clock);
  EXPECT_EQ(given.config.seed, 17);
}

}  // namespace
}  // namespace silva::pipeline
