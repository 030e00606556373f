// The specular and translucent parts of the shading: GGX against its analytic values, energy
// bounds, back-light transmission only from behind, the wet look's roughness, and the relief
// normals of bark, rock and the forest floor.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

#include "highway_targets.hpp"
#include "render/brdf.hpp"
#include "render/floor_litter.hpp"
#include "render/materials.hpp"
#include "core/value_noise.hpp"
#include "render/weather_look.hpp"

namespace silva::render {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Unit vector at polar angle theta from +Z in the XZ plane rotated by phi about Z.
Vec3f polar(double theta, double phi) {
  return Vec3f(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)));
}

TEST(ShadingBrdf, NormalIncidencePeakIsF0Over4PiAlphaSquared) {
  const Vec3f n(0, 0, 1);
  for (const float roughness : {0.3f, 0.5f, 0.8f, 1.0f})
    for (const float f0 : {0.02f, 0.04f, 1.0f}) {
      const double alpha = double(roughness) * roughness;
      const double expected = f0 / (4.0 * kPi * alpha * alpha);  // D = 1/(π α²), V = 1/4, F = F0
      EXPECT_NEAR(ggx_specular(n, n, n, roughness, f0), expected, 1e-5 * expected) << roughness << " " << f0;
    }
  // Below the sun's disc size the lobe stops narrowing.
  const double a = kMinSunAlpha;
  EXPECT_NEAR(ggx_specular(n, n, n, 0.01f, 0.04f), 0.04 / (4.0 * kPi * a * a), 1e-3);
}

TEST(ShadingBrdf, GgxDistributionIntegratesToOneOverProjectedArea) {
  for (const float alpha : {0.1f, 0.3f, 0.6f, 1.0f}) {
    double sum = 0;
    constexpr int kSteps = 20000;
    for (int k = 0; k < kSteps; ++k) {
      const double theta = (k + 0.5) * (kPi / 2) / kSteps;
      sum += ggx_distribution(float(std::cos(theta)), alpha) * std::cos(theta) * std::sin(theta);
    }
    EXPECT_NEAR(sum * 2 * kPi * (kPi / 2) / kSteps, 1.0, 2e-3) << alpha;
  }
}

TEST(ShadingBrdf, FresnelIsF0HeadOnAndOneAtGrazing) {
  EXPECT_FLOAT_EQ(schlick_fresnel(0.04f, 1.0f), 0.04f);
  EXPECT_FLOAT_EQ(schlick_fresnel(0.04f, 0.0f), 1.0f);
  // Karis's fit head-on: r1 = 0.0425 - 0.0275 r, weight = F0 (1.04 - 0.572 r - 1.04 r1) + 1.04 r1 + 0.022 r - 0.04.
  for (const float r : {0.2f, 0.5f, 0.8f}) {
    const float r1 = 0.0425f - 0.0275f * r;
    EXPECT_NEAR(ambient_specular_weight(1.0f, r, 0.04f), 0.04f * (1.04f - 0.572f * r - 1.04f * r1) + 1.04f * r1 + 0.022f * r - 0.04f, 1e-6);
  }
  // Grazing: a rough surface mirrors little, a water film much more; never more than at F0 = 1.
  EXPECT_LT(ambient_specular_weight(0.05f, 0.85f, 0.04f), 0.15f);
  EXPECT_GT(ambient_specular_weight(0.05f, 0.12f, 0.04f), 0.45f);
  for (float nv = 0.0f; nv <= 1.0f; nv += 0.1f)
    for (const float r : {0.1f, 0.5f, 0.9f}) {
      EXPECT_GE(ambient_specular_weight(nv, r, 0.04f), 0.0f);
      EXPECT_LE(ambient_specular_weight(nv, r, 0.04f), ambient_specular_weight(nv, r, 1.0f) + 1e-6f);
      EXPECT_LE(ambient_specular_weight(nv, r, 1.0f), 1.0f);
    }
  EXPECT_FLOAT_EQ(forest_sky_view(1.0f), 1.0f);
  EXPECT_FLOAT_EQ(forest_sky_view(0.0f), 0.3f);
  EXPECT_FLOAT_EQ(forest_sky_view(-0.5f), 0.3f);
}

TEST(ShadingBrdf, ReflectsNoMoreEnergyThanArrives) {
  // Directional albedo of the lobe with F0 = 1: at most 1; single scattering loses more the
  // rougher the surface (at α = 1 about two thirds), never most of it below.
  const Vec3f n(0, 0, 1);
  const std::map<float, double> at_least = {{0.3f, 0.85}, {0.6f, 0.6}, {1.0f, 0.25}};
  for (const float roughness : {0.3f, 0.6f, 1.0f})
    for (const double view_theta : {0.0, 0.6, 1.2}) {
      const Vec3f to_eye = polar(view_theta, 0.0);
      double sum = 0;
      constexpr int kTheta = 400, kPhi = 400;
      for (int i = 0; i < kTheta; ++i)
        for (int j = 0; j < kPhi; ++j) {
          const double theta = (i + 0.5) * (kPi / 2) / kTheta, phi = (j + 0.5) * 2 * kPi / kPhi;
          const Vec3f l = polar(theta, phi);
          sum += ggx_specular(n, to_eye, l, roughness, 1.0f) * std::cos(theta) * std::sin(theta);
        }
      const double albedo = sum * (kPi / 2 / kTheta) * (2 * kPi / kPhi);
      EXPECT_LE(albedo, 1.02) << roughness << " " << view_theta;
      EXPECT_GE(albedo, at_least.at(roughness)) << roughness << " " << view_theta;
    }
}

TEST(ShadingBrdf, LeavesTransmitOnlyWhenTheSunIsBehindThem) {
  EXPECT_EQ(back_light_transmission(0.5f, 0.9f), 0.0f);   // sun on the viewer's side of the card
  EXPECT_EQ(back_light_transmission(0.0f, 0.9f), 0.0f);
  EXPECT_GT(back_light_transmission(-0.5f, -0.3f), 0.0f);  // behind the card, looking away from the sun
  EXPECT_GT(back_light_transmission(-0.5f, 0.95f), back_light_transmission(-0.5f, 0.2f));  // glow towards the sun
  EXPECT_FLOAT_EQ(back_light_transmission(-0.5f, 0.0f), 0.5f);
}

TEST(ShadingBrdf, RainLowersRoughnessMostOnUpwardSurfaces) {
  WeatherPreset rain;
  rain.wetness = 1.0f;
  const WeatherLook wet(rain), dry(WeatherPreset{});
  const Vec3f up(0, 0, 1), side(1, 0, 0);
  EXPECT_EQ(dry.roughness(0.85f, up), 0.85f);
  EXPECT_LT(wet.roughness(0.85f, side), 0.85f * 0.5f);
  EXPECT_LT(wet.roughness(0.85f, up), wet.roughness(0.85f, side));
  EXPECT_GT(wet.roughness(0.85f, up), 0.0f);
  rain.wetness = 0.5f;
  const WeatherLook damp(rain);
  EXPECT_GT(damp.roughness(0.85f, up), wet.roughness(0.85f, up));
  EXPECT_LT(damp.roughness(0.85f, up), 0.85f);
}

TEST(ShadingBrdf, RainLeavesDarkMirrorPuddlesOnTheTrailOnly) {
  WeatherPreset rain;
  rain.wetness = 1.0f;
  const WeatherLook wet(rain), dry(WeatherPreset{});
  int puddles = 0, points = 0;
  for (int i = 0; i < 80; ++i)
    for (int j = 0; j < 80; ++j, ++points) {
      SurfacePoint s{Vec3f(0.25f * float(i) - 7.0f, 0.25f * float(j) + 3.0f, 0.0f), Vec3f::UnitZ(), Vec2f::Zero(),
                     Material::Trail, 1};
      const float p = wet.puddle(s);
      ASSERT_GE(p, 0.0f);
      ASSERT_LE(p, 1.0f);
      puddles += p > 0.5f ? 1 : 0;
      EXPECT_EQ(dry.puddle(s), 0.0f);
      s.material = Material::Ground;
      EXPECT_EQ(wet.puddle(s), 0.0f);  // the forest floor soaks it up
    }
  const double share = double(puddles) / points;
  EXPECT_GT(share, 0.08);
  EXPECT_LT(share, 0.45);
  const Vec3f up(0, 0, 1), mud(0.3f, 0.25f, 0.2f);
  const SurfacePoint trail{Vec3f::Zero(), up, Vec2f::Zero(), Material::Trail, 1};
  EXPECT_LT(wet.roughness(0.85f, up, 1.0f), 0.05f);
  EXPECT_EQ(wet.roughness(0.85f, up, 0.0f), wet.roughness(0.85f, up));
  EXPECT_TRUE((wet.albedo(mud, trail, 1.0f).array() < wet.albedo(mud, trail, 0.0f).array()).all());
}

TEST(ShadingBrdf, BarkAndRockReliefTiltsTheShadingNormalUpClose) {
  for (const Material m : {Material::BarkConifer, Material::BarkOak, Material::Rock, Material::LogBark}) {
    double tilt = 0;
    for (int k = 0; k < 100; ++k) {
      const SurfacePoint s{Vec3f(0.31f + 0.017f * float(k), 2.0f, 0.5f + 0.023f * float(k)), Vec3f(0, -1, 0),
                           Vec2f(0.5f, 0.5f), m, 1};
      const Vec3f n = material_shading_normal(s, 0.001f);
      EXPECT_NEAR(n.norm(), 1.0f, 1e-5f);
      EXPECT_GT(n.dot(s.normal), 0.5f);
      EXPECT_EQ(n, material_shading_normal(s, 0.001f));
      tilt += std::acos(std::min(1.0f, n.dot(s.normal)));
      EXPECT_EQ(material_shading_normal(s, 1.0f), s.normal);  // far away: faded out
    }
    EXPECT_GT(tilt / 100, 0.05) << material_name(m);  // a few degrees on average
  }
  const SurfacePoint leaf{Vec3f(1, 2, 3), Vec3f(0, 0, 1), Vec2f(0.5f, 0.5f), Material::Leaves, 1};
  EXPECT_EQ(material_shading_normal(leaf, 0.0f), leaf.normal);
}

/// The forest floor's relief height at p where the litter sprites have faded (materials.hpp), before the
/// fine-detail fade.
double ground_height(double x, double y) {
  return kGroundLeafRelief * value_noise2(float(9 * x), float(9 * y), kGroundLeafSalt) +
         kGroundSpeckleRelief * value_noise2(float(23 * x), float(23 * y), kGroundLeafSalt + 1);
}

TEST(ShadingBrdf, GroundSlopeIsTheReliefGradientOnEveryHighwayTarget) {
  std::vector<Vec3f> p, n(37, Vec3f(0, 0, 1)), albedo(37);
  for (int i = 0; i < 37; ++i) p.emplace_back(0.137f * float(i) - 2.0f, 0.071f * float(i * 7 % 37), 0.0f);
  // Up close (the sprites' tilts included) and where the sprites have faded (footprint kLitterFadeFar,
  // half of the fine detail left: the relief noises' gradient times 0.5).
  for (const float footprint_m : {0.0f, kLitterFadeFar}) {
    const std::vector<float> footprint(37, footprint_m);
    std::vector<Vec2f> first;
    for (int64_t target : test::highway_targets()) {
      const test::PinnedTarget pinned(target);
      std::vector<Vec2f> slope(p.size());
      ground_albedo_row(p.data(), n.data(), footprint.data(), p.size(), albedo.data(), nullptr, slope.data());
      if (first.empty()) first = slope;
      for (size_t i = 0; i < p.size(); ++i) {
        EXPECT_EQ(slope[i], first[i]) << hwy::TargetName(target) << " " << i;  // the same bits everywhere
        if (footprint_m == 0.0f) continue;
        const double h = 1e-4, x = p[i].x(), y = p[i].y();
        const double dx = 0.5 * (ground_height(x + h, y) - ground_height(x - h, y)) / (2 * h);
        const double dy = 0.5 * (ground_height(x, y + h) - ground_height(x, y - h)) / (2 * h);
        EXPECT_NEAR(slope[i].x(), dx, 0.01) << i;
        EXPECT_NEAR(slope[i].y(), dy, 0.01) << i;
      }
    }
  }
  // Far away (footprint beyond the fine-detail fade) the floor is flat.
  const std::vector<float> far(37, 0.2f);
  std::vector<Vec2f> slope(p.size());
  ground_albedo_row(p.data(), n.data(), far.data(), p.size(), albedo.data(), nullptr, slope.data());
  for (const Vec2f& s : slope) EXPECT_EQ(s, Vec2f::Zero());
}

}  // namespace
}  // namespace silva::render
