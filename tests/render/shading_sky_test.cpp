#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "highway_targets.hpp"
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

TEST(ShadingSky, FogAmountMatchesTheClosedFormIntegral) {
  LightingPreset day = preset_day();
  day.fog_density = 0.02f;
  day.fog_height_falloff = 0.05f;
  day.fog_height = 0.0f;
  const Sky sky(day);
  const Vec3f cam(3, -2, 1.5f);
  const HeightFog fog(day, sky, cam);
  // density(z) = 0.02 exp(-0.05 z); optical depth = integral of density along the ray.
  for (const Vec3f& p : {Vec3f(50, 10, 1.5f), Vec3f(-20, 80, 30.0f), Vec3f(3, -2, -40.0f), Vec3f(200, 0, 1.6f)}) {
    const double len = (p - cam).cast<double>().norm(), dz = double(p.z() - cam.z());
    const double k = 0.05 * dz;
    const double mean = std::abs(k) < 1e-9 ? 1.0 : (1.0 - std::exp(-k)) / k;
    const double expected = 1.0 - std::exp(-0.02 * std::exp(-0.05 * 1.5) * len * mean);
    EXPECT_NEAR(fog.amount(p), expected, 2e-6) << p.transpose();
  }
}

TEST(ShadingSky, FogAmountsAreIdenticalOnEveryHighwayTargetAndForAnyBatchLength) {
  const LightingPreset day = preset_day();
  const Sky sky(day);
  const HeightFog fog(day, sky, Vec3f(1, 2, 1.5f));
  std::vector<Vec3f> points;
  for (int i = 0; i < 37; ++i)  // odd count: full vectors plus a tail on every target
    points.emplace_back(float(i * 7 % 150) - 20.0f, float(i * 13 % 90), float(i % 9) * 4.0f - 6.0f + 1.5f);
  points.emplace_back(1, 2, 1.5f);      // at the camera: 0
  points.emplace_back(1, 2, 1.50001f);  // |k| below the series threshold
  const std::vector<int64_t> targets = test::highway_targets();
  ASSERT_GE(targets.size(), 2u);
  const std::vector<float> reference = [&] {
    const test::PinnedTarget portable(targets.back());
    std::vector<float> r(points.size());
    fog.amounts(points.data(), points.size(), r.data());
    return r;
  }();
  EXPECT_EQ(reference[37], 0.0f);
  for (int64_t target : targets) {
    const test::PinnedTarget pinned(target);
    ASSERT_EQ(fog_simd_target(), target);
    SCOPED_TRACE(hwy::TargetName(target));
    std::vector<float> all(points.size());
    fog.amounts(points.data(), points.size(), all.data());
    for (size_t i = 0; i < points.size(); ++i) {
      EXPECT_EQ(all[i], reference[i]) << i;
      EXPECT_EQ(fog.amount(points[i]), reference[i]) << i;  // a batch of one
    }
  }
}

TEST(ShadingSky, HemisphereLightIsSkyAboveGroundBelow) {
  const Sky sky(preset_day());
  EXPECT_EQ(sky.ambient(Vec3f(0, 0, 1)), sky.sky_light);
  EXPECT_EQ(sky.ambient(Vec3f(0, 0, -1)), sky.ground_light);
}

}  // namespace
}  // namespace silva::render
