#include "core/camera_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace silva {
namespace {

TEST(CameraModel, ConfigGivesTheModelAndTheFocalLength) {
  CameraConfig c;
  const Camera cam = Camera::from_fov(1920, 1080, 90, 0.05, 150);  // fx = 960
  CameraModel m = camera_model(c, cam);
  ASSERT_TRUE(m.noise);
  EXPECT_EQ(m.noise->full_well_e, 10000);
  EXPECT_EQ(m.noise->read_noise_e, 3);
  EXPECT_EQ(m.noise->gain, 2);
  EXPECT_EQ(m.noise->max_gain, 32);
  EXPECT_NEAR(m.noise->aperture_ev, std::log2(2.0 * 2.0 / 0.01), 1e-12);  // f/2 at 1/100 s
  EXPECT_EQ(m.vignetting, 0.25);
  EXPECT_FALSE(m.depth_of_field);
  EXPECT_FALSE(m.motion);  // per frame, not from the config
  c.noise = false;
  c.depth_of_field = true;
  c.sensor_width_mm = 12.0;
  m = camera_model(c, cam);
  EXPECT_FALSE(m.noise);
  ASSERT_TRUE(m.depth_of_field);
  EXPECT_NEAR(m.depth_of_field->focal_length_mm, 6.0, 1e-12);  // 90 degrees across 12 mm: 6 mm
}

TEST(CameraModel, DarkScenesRaiseTheGainUpToItsCeilingAndLoseColour) {
  CameraModel m;
  m.noise = SensorNoise{10000, 3, 2, 32, 8.0};  // gain 1 exposes scenes down to EV100 8
  // Bright scenes keep the base gain and every colour.
  for (double ev : {15.0, 9.0, 7.0}) {
    const CameraModel e = exposed_camera_model(m, ev);
    EXPECT_EQ(e.noise->gain, 2) << ev;
    EXPECT_EQ(e.chroma, 1.0) << ev;
  }
  // EV100 5: 2^(8 - 5) = 8, two stops above the base gain.
  CameraModel e = exposed_camera_model(m, 5.0);
  EXPECT_NEAR(e.noise->gain, 8.0, 1e-12);
  EXPECT_NEAR(e.chroma, 1.0 / (1.0 + 2.0 * kChromaLossPerStop), 1e-12);
  // Moonlight needs more than the ceiling: max_gain, four stops up.
  e = exposed_camera_model(m, -2.0);
  EXPECT_EQ(e.noise->gain, 32);
  EXPECT_NEAR(e.chroma, 1.0 / (1.0 + 4.0 * kChromaLossPerStop), 1e-12);
  EXPECT_EQ(e.noise->max_gain, 32);
  // Without noise there is no gain to raise.
  EXPECT_EQ(exposed_camera_model(CameraModel{}, -2.0), CameraModel{});
}

}  // namespace
}  // namespace silva
