#include "core/camera_model.hpp"

#include <gtest/gtest.h>


namespace silva {
namespace {

TEST(CameraModel, ConfigGivesTheModelAndTheFocalLength) {
  CameraConfig c;
  const Camera cam = Camera::from_fov(1920, 1080, 90, 0.05, 150);  // fx = 960
  CameraModel m = camera_model(c, cam);
  ASSERT_TRUE(m.noise);
  EXPECT_EQ(*m.noise, (SensorNoise{10000, 3, 2}));
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

}  // namespace
}  // namespace silva
