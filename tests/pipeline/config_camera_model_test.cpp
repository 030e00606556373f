#include <gtest/gtest.h>

#include "pipeline/config/config_checks.hpp"
#include "pipeline/config/config_loader.hpp"
#include "core/error.hpp"

namespace silva::pipeline {
namespace {

/// The InputError message of loading the defaults with these overrides, or "" when it loads.
std::string load_message(std::vector<std::string> sets) {
  try {
    load_config({"", std::move(sets), {}, {}});
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ConfigCameraModel, OutOfRangeValuesNameKeyAndRange) {
  EXPECT_EQ(load_message({"camera.full_well_e=50"}),
            "--set camera.full_well_e=50: camera.full_well_e = 50 is out of range (allowed: 100 to 1000000)");
  EXPECT_EQ(load_message({"camera.read_noise_e=-1"}),
            "--set camera.read_noise_e=-1: camera.read_noise_e = -1 is out of range (allowed: 0 to 1000)");
  EXPECT_EQ(load_message({"camera.gain=0.5"}),
            "--set camera.gain=0.5: camera.gain = 0.5 is out of range (allowed: 1 to 64)");
  EXPECT_EQ(load_message({"camera.vignetting=1.5"}),
            "--set camera.vignetting=1.5: camera.vignetting = 1.5 is out of range (allowed: 0 to 1)");
  EXPECT_EQ(load_message({"camera.chromatic_aberration=0.1"}),
            "--set camera.chromatic_aberration=0.1: camera.chromatic_aberration = 0.1 is out of range (allowed: 0 "
            "to 0.003)");
  EXPECT_EQ(load_message({"camera.bloom=0.2"}),
            "--set camera.bloom=0.2: camera.bloom = 0.2 is out of range (allowed: 0 to 0.1)");
  EXPECT_EQ(load_message({"camera.f_number=0.2"}),
            "--set camera.f_number=0.2: camera.f_number = 0.2 is out of range (allowed: 0.5 to 64)");
  EXPECT_EQ(load_message({"camera.shutter_s=0"}),
            "--set camera.shutter_s=0: camera.shutter_s = 0 is out of range (allowed: greater than 0, at most 1)");
  EXPECT_EQ(load_message({"camera.autopilot_speed=-2"}),
            "--set camera.autopilot_speed=-2: camera.autopilot_speed = -2 is out of range (allowed: greater than 0, "
            "at most 100)");
  EXPECT_EQ(load_message({"camera.noise=1"}),
            "--set camera.noise=1: camera.noise must be a boolean (true or false), got an integer (1)");
  EXPECT_EQ(load_message({"camera.gain=4", "camera.vignetting=0", "camera.depth_of_field=true",
                          "camera.chromatic_aberration=0.002", "camera.motion_blur=true"}),
            "");
}

TEST(ConfigCameraModel, FocusMustLieBeyondTheFocalLength) {
  // 10 degrees across a 100 mm sensor: a 0.1 / (2 tan 5 deg) = 0.5715 m lens.
  const std::string message = load_message({"camera.depth_of_field=true", "camera.sensor_width_mm=100",
                                            "camera.focus_distance=0.5", "camera.fov_deg=10"});
  EXPECT_EQ(message.rfind("config: camera.focus_distance = 0.5 must exceed the lens's focal length, 0.571", 0), 0u)
      << message;
  EXPECT_TRUE(message.ends_with(" m (from camera.sensor_width_mm and camera.fov_deg)")) << message;
  EXPECT_EQ(load_message({"camera.depth_of_field=true", "camera.sensor_width_mm=100", "camera.focus_distance=0.6",
                          "camera.fov_deg=10"}),
            "");
  EXPECT_EQ(load_message({"camera.depth_of_field=false", "camera.sensor_width_mm=100", "camera.focus_distance=0.5",
                          "camera.fov_deg=10"}),
            "");
}

TEST(ConfigCameraModel, FilmGrainNamesWhatReplacedIt) {
  const std::string expected =
      "key 'camera.film_grain' no longer exists; the sensor noise model replaced it: camera.noise, "
      "camera.full_well_e, camera.read_noise_e, camera.gain";
  EXPECT_EQ(load_message({"camera.film_grain=0.015"}), "--set camera.film_grain=0.015: " + expected);
  try {
    parse_config_text("[camera]\nfilm_grain = 0.015\n", "old.toml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "old.toml:2:14: " + expected);
  }
}

}  // namespace
}  // namespace silva::pipeline
