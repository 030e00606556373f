// rig.preset fills the rig.* keys a config leaves out, and never a key the file or --set gave; a rig with a LiDAR
// adds output type lidar once.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "pipeline/config/config_loader.hpp"

namespace silva::pipeline {
namespace {

/// The built-in defaults with `overrides` as --set.
Config loaded(std::vector<std::string> overrides) {
  ConfigSources sources;
  sources.overrides = std::move(overrides);
  return load_config(sources).config;
}

/// Times output type `type` appears in `c`.
long count_type(const Config& c, const std::string& type) {
  return std::count(c.output.types.begin(), c.output.types.end(), type);
}

TEST(RigPresetConfig, PresetsFillTheirValues) {
  struct Expected {
    const char* preset;
    int cameras;
    double height_m, pitch_deg;
    bool lidar;
  };
  for (const Expected& e : {Expected{"mono", 1, 0.0, 0.0, false}, Expected{"stereo", 2, 0.0, 0.0, false},
                            Expected{"ground_robot", 2, 0.55, 0.0, true}, Expected{"drone", 1, 3.0, -15.0, false}}) {
    const Config c = loaded({std::string("rig.preset=") + e.preset});
    EXPECT_EQ(c.rig.cameras, e.cameras) << e.preset;
    EXPECT_DOUBLE_EQ(c.rig.height_m, e.height_m) << e.preset;
    EXPECT_DOUBLE_EQ(c.rig.pitch_deg, e.pitch_deg) << e.preset;
    EXPECT_EQ(c.rig.lidar, e.lidar) << e.preset;
    EXPECT_EQ(count_type(c, "lidar"), e.lidar ? 1 : 0) << e.preset;  // a rig with a LiDAR adds it once
  }
  const Config defaults = loaded({});  // no rig.preset given: mono
  EXPECT_EQ(defaults.rig.cameras, 1);
  EXPECT_EQ(count_type(defaults, "lidar"), 0);
}

TEST(RigPresetConfig, KeysTheUserGaveWin) {
  const Config robot = loaded({"rig.preset=ground_robot", "rig.height_m=0.8", "rig.lidar=false", "rig.cameras=1"});
  EXPECT_EQ(robot.rig.cameras, 1);
  EXPECT_DOUBLE_EQ(robot.rig.height_m, 0.8);
  EXPECT_FALSE(robot.rig.lidar);
  EXPECT_EQ(count_type(robot, "lidar"), 0);
  // Given before the preset on the command line, a key still wins; lidar already chosen is not added twice.
  const Config drone = loaded({"rig.pitch_deg=-30", "output.types=[\"rgb\",\"lidar\"]", "rig.preset=drone", "rig.lidar=true"});
  EXPECT_DOUBLE_EQ(drone.rig.pitch_deg, -30.0);
  EXPECT_DOUBLE_EQ(drone.rig.height_m, 3.0);
  EXPECT_EQ(count_type(drone, "lidar"), 1);
}

TEST(RigPresetConfig, FileKeysWinToo) {
  const std::string path = ::testing::TempDir() + "rig_preset_config_test.toml";
  std::ofstream(path) << "[rig]\npreset = \"ground_robot\"\ncameras = 1\npitch_deg = -5\n";
  ConfigSources sources;
  sources.file = path;
  const Config c = load_config(sources).config;
  EXPECT_EQ(c.rig.cameras, 1);
  EXPECT_DOUBLE_EQ(c.rig.pitch_deg, -5.0);
  EXPECT_DOUBLE_EQ(c.rig.height_m, 0.55);  // left out: the preset's
  EXPECT_TRUE(c.rig.lidar);
}

}  // namespace
}  // namespace silva::pipeline
