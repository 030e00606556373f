#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "highway_targets.hpp"
#include "render/sky.hpp"
#include "render/sky_fog.hpp"
#include "render/sky_model.hpp"
#include "render/sky_sh.hpp"

namespace silva::render {
namespace {

constexpr double kPi = 3.14159265358979323846;

float luminance(const Vec3f& c) { return 0.2126f * c.x() + 0.7152f * c.y() + 0.0722f * c.z(); }

double rad(double deg) { return deg * kPi / 180.0; }

// Known answers evaluated by hand (a short Python script, independent of this code) from the
// formulas printed in Preetham, Shirley & Smits 1999, Appendix A.2:
//   Yz = (4.0453 T - 4.9710) tan χ - 0.2155 T + 2.4192, χ = (4/9 - T/120)(π - 2 θs)   [kcd/m²]
//   Y(θ, γ) / Yz = F(θ, γ) / F(0, θs), F = (1 + A e^(B/cos θ))(1 + C e^(D γ) + E cos² γ),
//   A..E of Y: 0.1787T-1.4630, -0.3554T+0.4275, -0.0227T+5.3251, 0.1206T-2.5771, -0.0670T+0.3703.
// At the horizon (θ = 90°) F's first factor is 1; away from the sun γ = 90° + elevation, towards it γ = elevation.
struct SkyAnswer {
  double turbidity, elevation_deg, zenith_y, horizon_away_ratio, horizon_towards_ratio;
};
constexpr SkyAnswer kSkyAnswers[] = {
    {3.0, 55.0, 9.228254, 0.897541, 1.333014},
    {3.0, 6.0, 2.403748, 1.835282, 8.664172},
    {5.0, 55.0, 16.231807, 0.480807, 0.815012},
};

TEST(ShadingSky, PreethamZenithLuminanceAndHorizonRatiosMatchThePaper) {
  for (const SkyAnswer& a : kSkyAnswers) {
    SCOPED_TRACE(testing::Message() << "T " << a.turbidity << " elevation " << a.elevation_deg);
    const PreethamSky sky(a.turbidity, rad(a.elevation_deg));
    EXPECT_NEAR(sky.zenith_y, a.zenith_y, 1e-5);
    EXPECT_NEAR(sky.luminance(1.0, kPi / 2 - rad(a.elevation_deg)), a.zenith_y, 1e-5);
    EXPECT_NEAR(sky.luminance(0.0, rad(90.0 + a.elevation_deg)) / sky.zenith_y, a.horizon_away_ratio, 1e-5);
    EXPECT_NEAR(sky.luminance(0.0, rad(a.elevation_deg)) / sky.zenith_y, a.horizon_towards_ratio, 1e-5);
  }
}

TEST(ShadingSky, PreethamZenithChromaticityMatchesThePaper) {
  // xz = [T² T 1] Mx [θs³ θs² θs 1]ᵀ and yz likewise with the paper's matrices, T = 3, θs = 35°.
  const PreethamSky sky(3.0, rad(55.0));
  EXPECT_NEAR(sky.zenith_x, 0.250368, 1e-6);
  EXPECT_NEAR(sky.zenith_cy, 0.256319, 1e-6);
  const Vec3d zenith = sky.rgb(1.0, kPi / 2 - rad(55.0));
  EXPECT_GT(zenith.z(), zenith.x());  // a clear zenith is blue
  EXPECT_NEAR(0.2126 * zenith.x() + 0.7152 * zenith.y() + 0.0722 * zenith.z(), sky.zenith_y, 2e-3 * sky.zenith_y);
}

TEST(ShadingSky, SunTransmittanceMatchesRayleighAndAerosolAttenuation) {
  // exp(-0.008735 λ^-4.08 m) exp(-(0.04608 T - 0.04586) λ^-1.3 m) at 610, 550, 465 nm, evaluated by
  // hand with Kasten's air mass m = 1 / (cos θs + 0.15 (93.885 - θs°)^-1.253): m(35°) = 1.219422, m(84°) = 8.847380.
  const Vec3d high = sun_transmittance(3.0, rad(55.0));
  EXPECT_NEAR(high.x(), 0.745108, 1e-6);
  EXPECT_NEAR(high.y(), 0.692699, 1e-6);
  EXPECT_NEAR(high.z(), 0.578661, 1e-6);
  const Vec3d low = sun_transmittance(3.0, rad(6.0));
  EXPECT_NEAR(low.x(), 0.118278, 1e-6);
  EXPECT_NEAR(low.y(), 0.069677, 1e-6);
  EXPECT_NEAR(low.z(), 0.018893, 1e-6);
}

TEST(ShadingSky, LowSunIsOrangeAndDimmerThanHighSun) {
  LightingPreset day = preset_day(), dusk = preset_dusk();
  day.cloud_cover = dusk.cloud_cover = 0;
  const Sky high(day), low(dusk);
  EXPECT_GT(low.sun_illuminance.x(), 3.0f * low.sun_illuminance.z());
  EXPECT_LT(high.sun_illuminance.x(), 1.5f * high.sun_illuminance.z());
  EXPECT_LT(luminance(low.sun_illuminance), 0.3f * luminance(high.sun_illuminance));
}

TEST(ShadingSky, TabulatedSkyFollowsTheModel) {
  LightingPreset day = preset_day();
  day.cloud_cover = 0;
  const Sky sky(day);
  const PreethamSky model(day.turbidity, rad(day.sun_elevation_deg));
  for (const Vec3f& d : {Vec3f(0, 0, 1), Vec3f(1, 0, 0.05f), Vec3f(-1, 0.3f, 0.4f), Vec3f(0.2f, -1, 0.7f)}) {
    const Vec3f dir = d.normalized();
    const double gamma = std::acos(std::clamp(double(dir.dot(sky.to_sun)), -1.0, 1.0));
    const double expected = model.luminance(double(dir.z()), gamma) * kPreethamSkyCalibration;
    EXPECT_NEAR(luminance(sky.diffuse(dir)), expected, 0.02 * expected) << dir.transpose();
  }
  EXPECT_GT(luminance(sky.radiance(sky.to_sun)), 1000.0f * luminance(sky.diffuse(Vec3f(0, 0, 1))));  // the disc clips
}

TEST(ShadingSky, ClearSkyLightMatchesMeasuredClearDays) {
  // Diffuse horizontal illuminance of a clear sky (IES fit, klx) at sun elevations from dawn to noon, and
  // direct sun about five to six times it at the day preset's elevation, as on real clear days.
  for (const float elevation : {6.0f, 15.0f, 30.0f, 45.0f, 55.0f, 70.0f}) {
    LightingPreset p = preset_day();
    p.cloud_cover = 0;
    p.sun_elevation_deg = elevation;
    const Sky sky(p);
    const double sky_h = luminance(horizontal_irradiance([&](const Vec3d& d) -> Vec3d {
      return sky.diffuse(d.cast<float>()).cast<double>();
    }).cast<float>());
    const double measured = 0.8 + 15.5 * std::sqrt(std::sin(rad(elevation)));
    EXPECT_NEAR(sky_h, measured, 0.1 * measured) << elevation;
    if (elevation == 55.0f) {
      const double sun_h = luminance(sky.sun_illuminance) * double(sky.to_sun.z());
      EXPECT_GT(sun_h / sky_h, 4.5);
      EXPECT_LT(sun_h / sky_h, 6.5);
    }
  }
}

TEST(ShadingSky, OvercastIsGreyFlatBrightestAtTheZenithWithNoSun) {
  LightingPreset p = preset_day();
  p.cloud_cover = 1.0f;
  const Sky sky(p);
  EXPECT_EQ(sky.sun_illuminance, Vec3f::Zero());
  const Vec3f zenith = sky.diffuse(Vec3f(0, 0, 1)), horizon = sky.diffuse(Vec3f(1, 0, 0));
  EXPECT_NEAR(luminance(horizon) / luminance(zenith), 1.0f / 3.0f, 1e-4f);  // CIE overcast: (1 + 2 cos θ) / 3
  EXPECT_NEAR(zenith.x(), zenith.z(), 1e-4f * zenith.z());                  // grey
  const Vec3f at_sun = sky.radiance(sky.to_sun), beside = sky.radiance((sky.to_sun + Vec3f(0, 0, 0.05f)).normalized());
  EXPECT_LT(luminance(at_sun), 2.0f * luminance(beside));  // no disc
}

TEST(ShadingSky, NightIsDarkWithStars) {
  const Sky night(preset_night()), day(preset_day());
  EXPECT_LT(luminance(night.diffuse(Vec3f(0, 0, 1))), 1e-4f * luminance(day.diffuse(Vec3f(0, 0, 1))));
  EXPECT_GT(night.diffuse(Vec3f(0, 0, 1)).z(), night.diffuse(Vec3f(0, 0, 1)).x());  // blue
  int stars = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3f d = Vec3f(0.3f + 0.00003f * float(i), 0.2f, 0.9f).normalized();
    if (luminance(night.radiance(d)) > 2.0f * luminance(night.diffuse(d))) ++stars;
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
      if ((sky.radiance(d) - sky.diffuse(d)).norm() > 0.05f * sky.diffuse(d).norm()) ++cloudy;
    }
    return cloudy;
  };
  EXPECT_EQ(cloudy_fraction(0.0f), 0);
  EXPECT_LT(cloudy_fraction(0.2f), cloudy_fraction(0.7f));
}

TEST(ShadingSky, ShFitReproducesAConstantSkyExactly) {
  // A uniform radiance L from every direction gives irradiance π L on every surface.
  const IrradianceSH sh = fit_irradiance_sh([](const Vec3d&) { return Vec3d(2.0, 1.0, 0.5); });
  for (const Vec3f& n : {Vec3f(0, 0, 1), Vec3f(0, 0, -1), Vec3f(1, 0, 0), Vec3f(0.6f, -0.48f, 0.64f)}) {
    const Vec3f e = sh.irradiance(n);
    EXPECT_NEAR(e.x(), 2.0 * kPi, 1e-5) << n.transpose();
    EXPECT_NEAR(e.y(), 1.0 * kPi, 1e-5) << n.transpose();
    EXPECT_NEAR(e.z(), 0.5 * kPi, 1e-5) << n.transpose();
  }
  EXPECT_NEAR(horizontal_irradiance([](const Vec3d&) { return Vec3d(1, 1, 1); }).x(), kPi, 1e-12);
}

TEST(ShadingSky, ShFitReproducesALinearInZSkyExactly) {
  // L(d) = a + b d.z: irradiance ∫ L max(n·d, 0) dω = π a + (2π/3) b n.z for every unit n.
  const double a = 3.0, b = 1.5;
  const IrradianceSH sh = fit_irradiance_sh([&](const Vec3d& d) { return Vec3d::Constant(a + b * d.z()); });
  for (const Vec3f& n : {Vec3f(0, 0, 1), Vec3f(0, 0, -1), Vec3f(0, 1, 0), Vec3f(0.6f, -0.48f, 0.64f),
                         Vec3f(-0.8f, 0.0f, -0.6f)}) {
    const double expected = kPi * a + 2.0 * kPi / 3.0 * b * double(n.z());
    EXPECT_NEAR(sh.irradiance(n).x(), expected, 1e-5 * expected) << n.transpose();
  }
}

TEST(ShadingSky, AmbientLightIsBrighterFromTheSkyThanFromTheGround) {
  const Sky sky(preset_day());
  // The ground (albedo 0.11) returns a ninth of sun and sky together, the sun being four times the sky.
  EXPECT_GT(luminance(sky.ambient(Vec3f(0, 0, 1))), 2.0f * luminance(sky.ambient(Vec3f(0, 0, -1))));
  EXPECT_GT(luminance(sky.ambient(Vec3f(0, 0, -1))), 0.0f);  // the ground's bounce
  LightingPreset dark = preset_day();
  dark.ambient_intensity = 0.0f;
  EXPECT_EQ(Sky(dark).ambient(Vec3f(0, 0, 1)), Vec3f::Zero());
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

TEST(ShadingSky, FogScattersTheLightAroundItMostTowardsTheSun) {
  LightingPreset day = preset_day();
  day.cloud_cover = 0;
  const Sky sky(day);
  const HeightFog fog(day, sky, Vec3f(0, 0, 1.5f));
  const Vec3f level_sun = Vec3f(sky.to_sun.x(), sky.to_sun.y(), 0).normalized();
  EXPECT_GT(luminance(fog.color(sky.to_sun)), luminance(fog.color(-level_sun)));
  // Away from the sun, fog is the light arriving from all around scattered evenly: the sphere's
  // mean sky and ground radiance plus the sun's illuminance over 4π, as much as the canopy and the
  // fog above the camera let through.
  const HeightFogLight through = fog_light_transmittance(day, sky.to_sun, 1.5f);
  const Vec3f expected =
      (sky.mean_radiance * through.diffuse + sky.sun_illuminance * float(1.0 / (4.0 * kPi)) * through.sun) *
      kFogCanopyOpenness;
  EXPECT_LT((fog.color(-level_sun) - expected).norm(), 1e-4f * expected.norm());
  LightingPreset overcast = day;
  overcast.cloud_cover = 1;
  const Sky grey(overcast);
  const Vec3f c = HeightFog(overcast, grey, Vec3f(0, 0, 1.5f)).color(Vec3f(1, 0, 0));
  EXPECT_NEAR(c.x(), c.z(), 0.1f * c.z());  // grey under an overcast (the brown ground bounce tints it a little)
}

TEST(ShadingSky, DenseFogShadesTheLightItScatters) {
  // Known answer: the day fog's column above 1.5 m has optical depth 0.004 e^(-0.08 x 1.5) / 0.08.
  const LightingPreset day = preset_day();
  const Vec3f to_sun = sun_direction(day);
  const double depth = 0.004 * std::exp(-0.08 * 1.5) / 0.08;
  const HeightFogLight thin = fog_light_transmittance(day, to_sun, 1.5f);
  EXPECT_NEAR(thin.diffuse, std::exp(-kDiffuseFogPath * depth), 1e-6);
  EXPECT_NEAR(thin.sun, std::exp(-depth / std::sin(55.0 * kPi / 180.0)), 1e-6);
  // Mist at night (six times the night's fog) lets through much less than a clear night's haze, and
  // the light reaching the fog grows with the camera's height above the fog layer.
  LightingPreset night = preset_night(), mist = preset_night();
  mist.weather = builtin_weathers().at("mist");
  mist = with_weather(mist);
  const HeightFogLight clear_night = fog_light_transmittance(night, sun_direction(night), 1.5f);
  const HeightFogLight misty_night = fog_light_transmittance(mist, sun_direction(mist), 1.5f);
  EXPECT_LT(misty_night.diffuse, 0.5f * clear_night.diffuse);
  EXPECT_LT(misty_night.sun, 0.5f * clear_night.sun);
  EXPECT_GT(fog_light_transmittance(mist, sun_direction(mist), 30.0f).diffuse, misty_night.diffuse);
  LightingPreset none = day;
  none.fog_density = 0;
  EXPECT_EQ(fog_light_transmittance(none, to_sun, 1.5f).diffuse, 1.0f);
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

}  // namespace
}  // namespace silva::render
