#include "pipeline/config/config_checks.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace silva::pipeline {
namespace {

/// The message check_config throws for a config built by `edit`, or "" when it passes.
template <class F>
std::string check_message(F&& edit) {
  LoadedConfig loaded;
  loaded.source = "a.toml";
  edit(loaded.config);
  try {
    check_config(loaded);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ConfigChecks, DefaultsPass) { EXPECT_EQ(check_message([](Config&) {}), ""); }

TEST(ConfigChecks, NearMustBeBelowFar) {
  EXPECT_EQ(check_message([](Config& c) { c.camera.near = 200; }),
            "a.toml: camera.near = 200 must be less than camera.far = 150");
}

TEST(ConfigChecks, ChunkSizeIsAWholeMultiple) {
  EXPECT_EQ(check_message([](Config& c) { c.terrain.vertex_spacing = 0.3; }),
            "a.toml: terrain.chunk_size = 32 must be a whole multiple of terrain.vertex_spacing = 0.3");
  EXPECT_EQ(check_message([](Config& c) { c.vegetation.grid_spacing = 3; }),
            "a.toml: terrain.chunk_size = 32 must be a whole multiple of vegetation.grid_spacing = 3");
  EXPECT_EQ(check_message([](Config& c) { c.terrain.vertex_spacing = 0.1; c.terrain.chunk_size = 25.6; c.vegetation.grid_spacing = 3.2; }), "");
  EXPECT_TRUE(is_whole_multiple(32, 0.1));
  EXPECT_FALSE(is_whole_multiple(1, 2));
}

TEST(ConfigChecks, CustomNeedsPosesFile) {
  EXPECT_EQ(check_message([](Config& c) { c.captures.sequences = {"custom"}; }),
            "a.toml: captures.sequences has \"custom\", which needs captures.poses_file");
  EXPECT_EQ(check_message([](Config& c) {
              c.captures.sequences = {"custom"};
              c.captures.poses_file = "poses.json";
            }),
            "");
}

TEST(ConfigChecks, SemanticKittiNeedsLidar) {
  EXPECT_EQ(check_message([](Config& c) { c.output.formats = {"semantickitti"}; }),
            "a.toml: output.formats has \"semantickitti\", which needs \"lidar\" in output.types");
  EXPECT_EQ(check_message([](Config& c) {
              c.output.formats = {"semantickitti"};
              c.output.types = {"lidar"};
            }),
            "");
}

TEST(ConfigChecks, SomeSequenceIsLeft) {
  EXPECT_EQ(check_message([](Config& c) { c.captures.sequences = {}; }),
            "a.toml: captures.sequences is empty (allowed: one or more of autopilot, random, custom, trajectory)");
  EXPECT_EQ(check_message([](Config& c) {
              c.captures.sequences = {"autopilot"};
              c.trail.enabled = false;
            }),
            "a.toml: the autopilot and trajectory sequences need trail.enabled = true, and no other sequence is "
            "left in captures.sequences");
  EXPECT_NE(check_message([](Config& c) {
              c.captures.sequences = {"trajectory"};
              c.trail.enabled = false;
            }),
            "");
  EXPECT_EQ(check_message([](Config& c) { c.trail.enabled = false; }), "");  // random remains
}

TEST(ConfigChecks, FrameNumbersFitSixDigits) {
  EXPECT_EQ(check_message([](Config& c) { c.captures.autopilot_points = 400000; }),
            "a.toml: captures.autopilot_points x len(captures.autopilot_yaws) = 1200000 frames, "
            "allowed at most 1000000");
}

TEST(ConfigChecks, TimeOfDayNamesAPreset) {
  EXPECT_EQ(check_message([](Config& c) { c.lighting.time_of_day = "noon"; }),
            "a.toml: lighting.time_of_day = \"noon\" is not a preset (allowed: day, dusk, night, "
            "or define [lighting.presets.noon])");
  EXPECT_EQ(check_message([](Config& c) { c.lighting.time_of_day = "night"; }), "");
  EXPECT_EQ(check_message([](Config& c) { c.lighting.weather = "hail"; }),
            "a.toml: lighting.weather = \"hail\" is not a weather preset (allowed: clear, mist, overcast, rain, snow, "
            "or define [lighting.weather_presets.hail])");
  EXPECT_EQ(check_message([](Config& c) { c.lighting.weather = "snow"; }),
            "a.toml: lighting.weather = \"snow\" lays snow, which needs vegetation.season = \"winter\" (got "
            "\"summer\"): bare deciduous crowns; snow on leaves is no real look");
  EXPECT_EQ(check_message([](Config& c) {
              c.lighting.weather = "snow";
              c.vegetation.season = "winter";
            }),
            "");
}

TEST(ConfigChecks, RandomizedSnowNeedsWinterToo) {
  const auto snow_drawn = [](Config& c) {
    c.lighting.randomize.enabled = true;
    c.lighting.randomize.weathers = {"clear", "snow"};
    c.lighting.randomize.weather_weights = {1, 1};
  };
  EXPECT_EQ(check_message(snow_drawn),
            "a.toml: lighting.randomize.weathers's \"snow\" lays snow, which needs vegetation.season = \"winter\" "
            "(got \"summer\"): bare deciduous crowns; snow on leaves is no real look");
  EXPECT_EQ(check_message([&](Config& c) {  // a snow preset that is never drawn is no snow
              snow_drawn(c);
              c.lighting.randomize.weather_weights = {1, 0};
            }),
            "");
  EXPECT_EQ(check_message([&](Config& c) {  // randomize replaces lighting.weather
              snow_drawn(c);
              c.lighting.randomize.weathers = {"clear"};
              c.lighting.randomize.weather_weights = {1};
              c.lighting.weather = "snow";
            }),
            "");
}

TEST(ConfigChecks, OutputDirIsSet) {
  EXPECT_EQ(check_message([](Config& c) { c.output.dir = ""; }), "a.toml: output.dir must not be empty");
}

}  // namespace
}  // namespace silva::pipeline
