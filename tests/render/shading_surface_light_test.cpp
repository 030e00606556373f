#include "render/surface_light.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "highway_targets.hpp"

namespace silva::render {
namespace {

/// A random unit vector.
Vec3f unit(std::mt19937& rng) {
  std::normal_distribution<float> g;
  Vec3f v(g(rng), g(rng), g(rng));
  return v / v.norm();
}

/// Random surface samples covering the combine's branches: normals facing towards and away from
/// the sun and the eye, lit, half-shadowed and shadowed, opaque and translucent, with and without
/// fog, open and under the canopy, every roughness the lanes take (from kSharpReflection to 1).
std::vector<SurfaceSample> samples(uint32_t seed, size_t count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u01(0.0f, 1.0f);
  const float steps[] = {0.0f, 0.0f, 0.3f, 1.0f};
  std::vector<SurfaceSample> out;
  for (size_t i = 0; i < count; ++i) {
    SurfaceSample s;
    s.albedo = Vec3f(u01(rng), u01(rng), u01(rng)) * 0.6f;
    s.normal = unit(rng);
    s.card_normal = i % 3 == 0 ? s.normal : unit(rng);
    s.view_dir = unit(rng);
    s.roughness = kSharpReflection + (1.0f - kSharpReflection) * u01(rng);
    if (i % 7 == 0) s.roughness = kSharpReflection;
    s.f0 = i % 2 == 0 ? 0.04f : 0.02f + 0.05f * u01(rng);
    s.translucency = steps[i % 4];
    s.ao = u01(rng);
    s.sun_visible = steps[(i / 4) % 4];
    s.fog = i % 5 == 0 ? 0.0f : u01(rng) * 0.8f;
    s.canopy = i % 6 == 0 ? 0.0f : u01(rng);
    out.push_back(s);
  }
  return out;
}

/// The lit preset, with its weather's changes, of a time of day and a weather.
LightingPreset preset(const std::string& time_of_day, const std::string& weather) {
  LightingPreset p = builtin_presets().at(time_of_day);
  p.weather = builtin_weathers().at(weather);
  return p;
}

TEST(SurfaceLight, LanesMatchOnePixelAtATimeOnEveryHighwayTarget) {
  // 203 samples: a batch that ends inside a vector.
  const std::vector<SurfaceSample> in = samples(7, 203);
  for (const auto& [time, weather] : {std::pair{"day", "clear"}, std::pair{"dusk", "mist"},
                                      std::pair{"night", "clear"}, std::pair{"day", "rain"}}) {
    SCOPED_TRACE(std::string(time) + " " + weather);
    const LightingPreset lit = with_weather(preset(time, weather));
    const Sky sky(lit);
    const HeightFog fog(lit, sky, Vec3f(3.0f, -2.0f, 1.6f));
    const SurfaceLighting lighting(sky, fog, lit);
    SurfaceBatch batch;
    batch.start(in.size());
    std::vector<Vec3f> want;
    for (const SurfaceSample& s : in) {
      batch.push(s);
      want.push_back(light_surface(lighting, s));
    }
    batch.pad();
    ASSERT_EQ(batch.size(), in.size());
    ASSERT_EQ(batch.padded_size() % SurfaceBatch::kPadding, 0u);
    for (int64_t target : test::highway_targets()) {
      SCOPED_TRACE(hwy::TargetName(target));
      const test::PinnedTarget pin(target);
      std::vector<Vec3f> got(batch.padded_size());
      light_rough_surfaces(lighting, batch, got.data());
      size_t differing = 0;
      for (size_t i = 0; i < in.size(); ++i)
        for (int c = 0; c < 3; ++c)
          differing += std::bit_cast<uint32_t>(got[i][c]) != std::bit_cast<uint32_t>(want[i][c]) ? 1 : 0;
      EXPECT_EQ(differing, 0u) << "first sample: " << got[0].transpose() << " want " << want[0].transpose();
    }
  }
}

/// The clear day's lighting at a camera 1.6 m up.
struct ClearDay {
  LightingPreset lit = with_weather(preset("day", "clear"));
  Sky sky{lit};
  HeightFog fog{lit, sky, Vec3f(0.0f, 0.0f, 1.6f)};
  SurfaceLighting lighting{sky, fog, lit};
};

TEST(SurfaceLight, SunLightsOnlyWhatFacesItAndBackLightPassesTranslucentCards) {
  const ClearDay day;
  const Sky& sky = day.sky;
  const SurfaceLighting& lighting = day.lighting;
  SurfaceSample s;
  s.albedo = Vec3f(0.3f, 0.3f, 0.3f);
  s.view_dir = Vec3f(1.0f, 0.0f, 0.0f);
  s.normal = s.card_normal = sky.to_sun;
  const Vec3f lit_face = light_surface(lighting, s);
  s.sun_visible = 0.0f;
  const Vec3f shadowed = light_surface(lighting, s);
  EXPECT_GT(lit_face.sum(), 2.0f * shadowed.sum());
  s.sun_visible = 1.0f;
  s.normal = s.card_normal = -sky.to_sun;  // the sun is behind the card
  const Vec3f opaque = light_surface(lighting, s);
  s.translucency = 1.0f;
  const Vec3f leaf = light_surface(lighting, s);
  EXPECT_GT(leaf.y(), opaque.y());
}

TEST(SurfaceLight, TheCanopyTakesSkyLightAndGivesBackLessGreenLight) {
  const ClearDay day;
  const SurfaceLighting& lighting = day.lighting;
  SurfaceSample s;
  s.albedo = Vec3f(0.3f, 0.3f, 0.3f);
  s.view_dir = Vec3f(1.0f, 0.0f, -0.2f).normalized();
  s.normal = s.card_normal = Vec3f(0.0f, 0.0f, 1.0f);
  s.sun_visible = 0.0f;
  const Vec3f open = light_surface(lighting, s);
  s.canopy = 1.0f;
  const Vec3f closed = light_surface(lighting, s);
  // Under a closed canopy only its scattered light is left: the albedo x canopy light / pi, no sky.
  const Vec3f want = s.albedo.cwiseProduct(lighting.canopy_light) * 0.318309886f;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(closed[c], want[c], 1e-4f * want[c]);
  EXPECT_LT(closed.sum(), 0.25f * open.sum());
  EXPECT_GT(closed.y(), closed.x());  // the leaves pass green
  EXPECT_GT(closed.x(), closed.z());
}

TEST(SurfaceLight, FogOverASurfaceUnderTreesIsInTheirShade) {
  const ClearDay day;
  SurfaceSample s;
  s.albedo = Vec3f::Zero();  // only the fog's light reaches the eye
  s.view_dir = Vec3f(1.0f, 0.0f, -0.1f).normalized();
  s.normal = s.card_normal = Vec3f(0.0f, 0.0f, 1.0f);
  s.sun_visible = 0.0f;
  s.roughness = 1.0f;
  s.f0 = 0.0f;
  s.fog = 0.3f;
  const Vec3f open = light_surface(day.lighting, s);
  s.canopy = 0.75f;
  const Vec3f shaded = light_surface(day.lighting, s);
  const float kept = 1.0f - kFogCanopyShade * 0.75f;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(shaded[c], kept * open[c], 1e-3f * open[c]);  // nothing but fog here
  s.canopy = 1.0f;
  EXPECT_LT(light_surface(day.lighting, s).sum(), (1.0f - kFogCanopyShade + 1e-3f) * open.sum());
  s.fog = 0.0f;
  s.canopy = 0.0f;
  EXPECT_LT(light_surface(day.lighting, s).sum(), 0.2f * open.sum());  // the fog was most of it
}

}  // namespace
}  // namespace silva::render
