// Trail surface families: each its own look, only on the trail band, water standing only in a muddy
// trail's ruts.
#include "render/trail_material.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/surface_overlay.hpp"
#include "render/lighting.hpp"
#include "render/weather_look.hpp"

namespace silva::render {
namespace {

/// A trail point of `family` at position p, `in` metres inside the trail's edge (negative: outside).
SurfacePoint trail_point(TrailSurface family, const Vec3f& p, float in) {
  SurfacePoint s{p, Vec3f::UnitZ(), Vec2f(-in, p.x()), Material::Trail, 1};
  s.trail = family;
  return s;
}

/// Mean albedo of `family` over a 3 m x 1.5 m grid of points between 0.1 and 0.7 m inside the edge.
Vec3f mean_albedo(TrailSurface family, float in_min = 0.1f, float in_max = 0.7f) {
  Vec3f sum = Vec3f::Zero();
  int n = 0;
  for (int i = 0; i < 120; ++i)
    for (int j = 0; j < 24; ++j, ++n) {
      const float in = in_min + (in_max - in_min) * (float(j) + 0.5f) / 24.0f;
      const Vec3f a = trail_albedo(trail_point(family, Vec3f(10.0f + 0.025f * float(i), 5.0f + 0.06f * float(j), 0.0f), in));
      EXPECT_TRUE(a.allFinite());
      EXPECT_GE(a.minCoeff(), 0.0f);
      EXPECT_LE(a.maxCoeff(), 1.0f);
      sum += a;
    }
  return sum / float(n);
}

/// Saturation-like spread of a colour: (max - min) / max.
float spread(const Vec3f& c) { return (c.maxCoeff() - c.minCoeff()) / c.maxCoeff(); }

TEST(TrailSurface, EveryFamilyLooksDifferentFromPackedEarth) {
  const Vec3f earth = mean_albedo(TrailSurface::PackedEarth);
  for (int f = 1; f < kTrailSurfaceCount; ++f)
    EXPECT_GT((mean_albedo(TrailSurface(f)) - earth).norm(), 0.01f) << trail_surface_name(TrailSurface(f));
  const Vec3f gravel = mean_albedo(TrailSurface::Gravel), mud = mean_albedo(TrailSurface::Muddy);
  const Vec3f roots = mean_albedo(TrailSurface::Roots);
  EXPECT_LT(spread(gravel), 0.6f * spread(earth));  // grey stones, not brown soil
  EXPECT_LT(mud.sum(), 0.6f * earth.sum());          // dark mud
  EXPECT_LT(roots.sum(), 0.8f * earth.sum());        // dark eroded soil
  // Grass between the ruts: green where the middle of the trail is (over 0.6 m in).
  const Vec3f middle = mean_albedo(TrailSurface::GrassRuts, 0.6f, 0.75f);
  EXPECT_GT(middle.y(), middle.x());
  EXPECT_GT(middle.y(), middle.z());
  const Vec3f rut = mean_albedo(TrailSurface::GrassRuts, 0.2f, 0.35f);
  EXPECT_GT(rut.x(), rut.y());  // bare soil in the ruts
}

TEST(TrailSurface, OutsideTheTrailEveryFamilyIsTheSameFloor) {
  for (int k = 0; k < 32; ++k) {
    const Vec3f p(3.0f + 0.41f * float(k), -2.0f + 0.17f * float(k), 0.0f);
    const Vec3f floor = trail_albedo(trail_point(TrailSurface::PackedEarth, p, -(kOverlayMargin + kOverlayRagged)));
    const Vec3f fringe = trail_albedo(trail_point(TrailSurface::PackedEarth, p, -0.2f));
    for (int f = 1; f < kTrailSurfaceCount; ++f) {
      EXPECT_EQ(trail_albedo(trail_point(TrailSurface(f), p, -(kOverlayMargin + kOverlayRagged))), floor);
      EXPECT_EQ(trail_albedo(trail_point(TrailSurface(f), p, -0.2f)), fringe);  // the worn fringe is shared
    }
  }
}

TEST(TrailSurface, WaterStandsOnlyInAMuddyTrailsRuts) {
  int in_ruts = 0, wet = 0;
  for (int i = 0; i < 400; ++i)
    for (int j = 0; j < 20; ++j) {
      const float in = -0.3f + 1.1f * float(j) / 19.0f;  // from outside the edge to the middle
      const Vec3f p(0.1f * float(i), 2.0f + 0.05f * float(j), 0.0f);
      for (int f = 0; f < kTrailSurfaceCount; ++f) {
        if (TrailSurface(f) != TrailSurface::Muddy) {
          EXPECT_EQ(trail_standing_water(trail_point(TrailSurface(f), p, in)), 0.0f);
        }
      }
      SurfacePoint mud = trail_point(TrailSurface::Muddy, p, in);
      const float water = trail_standing_water(mud);
      ASSERT_GE(water, 0.0f);
      ASSERT_LE(water, 1.0f);
      if (water > 0.0f) {  // only well inside the (ragged) edge, where the pixel is labelled trail
        EXPECT_LT(overlay_edge(mud.uv.x(), p), -0.05f) << in;
      }
      if (in > 0.62f + kOverlayRagged) {
        EXPECT_EQ(water, 0.0f) << in;  // not in the middle
      }
      if (in > 0.2f && in < 0.4f) {
        ++in_ruts;
        wet += water > 0.5f ? 1 : 0;
      }
      mud.material = Material::Ground;
      EXPECT_EQ(trail_standing_water(mud), 0.0f);
    }
  const double share = double(wet) / in_ruts;
  EXPECT_GT(share, 0.1);
  EXPECT_LT(share, 0.6);
}

TEST(TrailSurface, AMuddyTrailIsWetUnderADrySky) {
  const WeatherPreset dry;
  const WeatherLook muddy(dry, TrailSurface::Muddy), earth(dry, TrailSurface::PackedEarth);
  EXPECT_TRUE(muddy.active());
  EXPECT_FALSE(earth.active());
  const SurfacePoint trail = trail_point(TrailSurface::Muddy, Vec3f(1, 2, 0), 0.3f);
  SurfacePoint ground = trail;
  ground.material = Material::Ground;
  EXPECT_EQ(muddy.wetness(trail), kMudWetness);
  EXPECT_EQ(muddy.wetness(ground), 0.0f);
  EXPECT_LT(muddy.roughness(trail, 0.85f, Vec3f::UnitZ(), 0.0f), 0.85f);
  EXPECT_EQ(muddy.roughness(ground, 0.85f, Vec3f::UnitZ(), 0.0f), 0.85f);
  const Vec3f soil(0.2f, 0.15f, 0.1f);
  EXPECT_LT(muddy.albedo(soil, trail, 0.0f).sum(), soil.sum());
  EXPECT_EQ(muddy.albedo(soil, ground, 0.0f), soil);
  WeatherPreset rain;
  rain.wetness = 1.0f;
  EXPECT_EQ(WeatherLook(rain, TrailSurface::Muddy).wetness(trail), 1.0f);  // rain is wetter than mud
}

}  // namespace
}  // namespace silva::render
