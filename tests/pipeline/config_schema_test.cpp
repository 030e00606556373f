#include "pipeline/config/config_schema.hpp"

#include <gtest/gtest.h>

#include <set>

namespace silva::pipeline {
namespace {

TEST(ConfigSchema, HasEveryContractKeyOnce) {
  std::set<std::string_view> names;
  for (const ConfigKey& key : config_schema()) EXPECT_TRUE(names.insert(key.name).second) << key.name;
  for (std::string_view name :
       {"seed", "output.dir", "output.resolution", "output.types", "lighting.time_of_day", "lighting.weather",
        "captures.sequences", "captures.random_count", "captures.autopilot_points",
        "captures.autopilot_yaws", "captures.aerial", "captures.poses_file", "camera.fov_deg",
        "camera.near", "camera.far", "camera.ground_height", "camera.aerial_height",
        "camera.aerial_pitch_deg", "camera.antialias", "camera.noise", "camera.full_well_e",
        "camera.read_noise_e", "camera.gain", "camera.vignetting", "camera.chromatic_aberration", "camera.bloom",
        "camera.depth_of_field", "camera.f_number", "camera.focus_distance", "camera.sensor_width_mm",
        "camera.motion_blur", "camera.shutter_s", "camera.autopilot_speed", "vegetation.density",
        "vegetation.grid_spacing", "vegetation.ground", "vegetation.season", "vegetation.forest_type", "terrain.max_elevation", "terrain.octaves",
        "terrain.lacunarity", "terrain.persistence", "terrain.frequency", "terrain.chunk_size",
        "terrain.vertex_spacing", "trail.enabled", "trail.width", "trail.control_points",
        "trail.control_spacing", "world.extent", "world.render_distance", "render.lod",
        "render.ground_cover_distance", "captures.clearance", "captures.aerial_crown_clearance",
        "captures.ground_crown_clearance", "lidar.preset",
        "lidar.mount_offset", "lidar.mount_rpy_deg", "lidar.motion_distortion", "lighting.exposure", "lighting.exposure_compensation",
        "lighting.randomize.enabled", "lighting.randomize.sun_elevation_deg", "lighting.randomize.sun_azimuth_deg",
        "lighting.randomize.cloud_cover", "lighting.randomize.fog_density_scale",
        "lighting.randomize.exposure_compensation_ev", "lighting.randomize.white_balance_k",
        "lighting.randomize.weathers", "lighting.randomize.weather_weights", "trajectory.speed",
        "trajectory.duration_s", "trajectory.start_m", "trajectory.camera_hz", "trajectory.imu_hz", "trajectory.bob_m",
        "trajectory.sway_deg", "trajectory.step_hz", "trajectory.imu_noise", "trajectory.flow"}) {
    EXPECT_NE(find_key(name), nullptr) << name;
  }
  EXPECT_EQ(names.size(), 92u);
  EXPECT_EQ(find_key("threads"), nullptr);  // CLI only (CONTRACT.md)
}

TEST(ConfigSchema, FieldTypeMatchesKeyType) {
  Config config;
  for (const ConfigKey& key : config_schema()) {
    const FieldRef field = key.field(config);
    switch (key.type) {
      case ValueType::Int:
        EXPECT_TRUE(std::holds_alternative<int*>(field) || std::holds_alternative<int64_t*>(field)) << key.name;
        break;
      case ValueType::Float: EXPECT_TRUE(std::holds_alternative<double*>(field)) << key.name; break;
      case ValueType::Bool: EXPECT_TRUE(std::holds_alternative<bool*>(field)) << key.name; break;
      case ValueType::String: EXPECT_TRUE(std::holds_alternative<std::string*>(field)) << key.name; break;
      case ValueType::Resolution: EXPECT_TRUE(std::holds_alternative<ResolutionRef>(field)) << key.name; break;
      case ValueType::StringList:
        EXPECT_TRUE(std::holds_alternative<std::vector<std::string>*>(field)) << key.name;
        break;
      case ValueType::FloatList:
        EXPECT_TRUE(std::holds_alternative<std::vector<double>*>(field)) << key.name;
        break;
    }
  }
}

TEST(ConfigSchema, DefaultsAreInsideTheirRanges) {
  Config config;
  config.seed = 1;
  for (const ConfigKey& key : config_schema()) {
    const FieldRef field = key.field(config);
    if (const auto* d = std::get_if<double*>(&field)) {
      EXPECT_TRUE(key.range.contains(**d)) << key.name;
    }
    if (const auto* i = std::get_if<int*>(&field)) {
      EXPECT_TRUE(key.range.contains(**i)) << key.name;
    }
  }
}

TEST(ConfigSchema, SuggestsClosestKey) {
  EXPECT_EQ(closest_key("camera.fovdeg"), "camera.fov_deg");
  EXPECT_EQ(closest_key("camera.fov"), "camera.fov_deg");
  EXPECT_EQ(closest_key("camra.near"), "camera.near");
  EXPECT_EQ(closest_key("vegetation.densty"), "vegetation.density");
  EXPECT_EQ(closest_key("output.type"), "output.types");
  EXPECT_EQ(closest_key("sed"), "seed");
}

TEST(ConfigSchema, RangesDescribeThemselves) {
  EXPECT_EQ(find_key("camera.fov_deg")->allowed(), "10 to 170");
  EXPECT_EQ(find_key("seed")->allowed(), "0 to 9999999999");
  EXPECT_EQ(find_key("camera.near")->allowed(), "greater than 0, at most 1000000");
  EXPECT_FALSE(find_key("camera.near")->range.contains(0));
  EXPECT_TRUE(find_key("vegetation.density")->range.contains(25));
  EXPECT_FALSE(find_key("vegetation.density")->range.contains(25.5));
  EXPECT_FALSE(find_key("camera.vignetting")->range.contains(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_EQ(find_key("camera.film_grain"), nullptr);  // replaced by the sensor noise model
}

TEST(ConfigSchema, SplitsNames) {
  EXPECT_EQ(find_key("camera.fov_deg")->section(), "camera");
  EXPECT_EQ(find_key("camera.fov_deg")->leaf(), "fov_deg");
  EXPECT_EQ(find_key("seed")->section(), "");
  EXPECT_TRUE(is_section("terrain"));
  EXPECT_FALSE(is_section("terrain.octaves"));
}

}  // namespace
}  // namespace silva::pipeline
