#include <gtest/gtest.h>

#include "render/sky.hpp"
#include "render/sky_fog.hpp"

namespace silva::render {
namespace {

float luminance(const Vec3f& c) { return 0.2126f * c.x() + 0.7152f * c.y() + 0.0722f * c.z(); }

TEST(ShadingSky, DaySkyIsBlueAboveBrightAtTheHorizonAndTheSunOutshinesIt) {
  LightingPreset day = preset_day();
  day.cloud_cover = 0;
  const Sky sky(day);
  const Vec3f zenith = sky.radiance(Vec3f(0, 0, 1));
  const Vec3f away_horizon = sky.radiance(-Vec3f(sky.to_sun.x(), sky.to_sun.y(), 0).normalized());
  EXPECT_GT(zenith.z(), zenith.x());
  EXPECT_GT(luminance(away_horizon), luminance(zenith));
  EXPECT_GT(luminance(sky.radiance(sky.to_sun)), 10.0f * luminance(zenith));
}

TEST(ShadingSky, NightIsDarkWithAMoonAndStars) {
  const Sky night(preset_night()), day(preset_day());
  EXPECT_LT(luminance(night.gradient(Vec3f(0, 0, 1))), 0.05f * luminance(day.gradient(Vec3f(0, 0, 1))));
  EXPECT_GT(luminance(night.radiance(night.to_sun)), 1.0f);
  int stars = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3f d = Vec3f(0.3f + 0.00003f * float(i), 0.2f, 0.9f).normalized();
    if (luminance(night.radiance(d)) > 2.0f * luminance(night.gradient(d))) ++stars;
  }
  EXPECT_GT(stars, 0);
}

TEST(ShadingSky, CloudsFollowCloudCover) {
  auto cloudy_fraction = [](float cover) {
    LightingPreset p = preset_day();
    p.cloud_cover = cover;
    const Sky sky(p);
    int cloudy = 0;
    for (int i = 0; i < 4000; ++i) {
      const Vec3f d = Vec3f(float(i % 63) * 0.03f - 0.9f, float(i / 63) * 0.03f - 0.9f, 1.0f).normalized();
      if ((sky.radiance(d) - sky.gradient(d)).norm() > 0.05f) ++cloudy;
    }
    return cloudy;
  };
  EXPECT_EQ(cloudy_fraction(0.0f), 0);
  EXPECT_LT(cloudy_fraction(0.2f), cloudy_fraction(0.7f));
}

TEST(ShadingSky, FogGrowsWithDistanceAndThinsWithHeight) {
  const LightingPreset day = preset_day();
  const Sky sky(day);
  const HeightFog fog(day, sky, Vec3f(0, 0, 1.5f));
  EXPECT_EQ(fog.amount(Vec3f(0, 0, 1.5f)), 0.0f);
  EXPECT_LT(fog.amount(Vec3f(10, 0, 1.5f)), fog.amount(Vec3f(100, 0, 1.5f)));
  EXPECT_LT(fog.amount(Vec3f(100, 0, 60.0f)), fog.amount(Vec3f(100, 0, 1.5f)));
  EXPECT_LT(fog.amount(Vec3f(1e6f, 0, 1.5f)), 1.0f + 1e-6f);
  EXPECT_GT(fog.amount(Vec3f(1e5f, 0, 1.5f)), 0.99f);
}

TEST(ShadingSky, HemisphereLightIsSkyAboveGroundBelow) {
  const Sky sky(preset_day());
  EXPECT_EQ(sky.ambient(Vec3f(0, 0, 1)), sky.sky_light);
  EXPECT_EQ(sky.ambient(Vec3f(0, 0, -1)), sky.ground_light);
}

}  // namespace
}  // namespace silva::render
