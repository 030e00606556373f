#include <gtest/gtest.h>

#include <cmath>

#include "core/value_noise.hpp"
#include "render/floor_litter.hpp"
#include "render/noise_salts.hpp"

namespace silva::render {
namespace {

const Vec3f kFloor(0.1f, 0.1f, 0.1f);  ///< A grey floor under the cones.

/// The floor colour after the spruce cones at (x, y), seen sharp.
Vec3f cones_at(float x, float y, float density, float weight = 1.0f, float footprint = 1e-4f) {
  Vec3f c = kFloor;
  Vec2f slope(0.0f, 0.0f);
  spruce_cones(x, y, footprint, density, weight, c, slope);
  return c;
}

/// A cell's cone as its hashes draw it: kept where the litter is all spruce needles, its hue, half
/// length (metres), centre (metres) and unit axis.
struct Cone {
  bool kept;
  float hue, half_length, x, y, ux, uy;
};

Cone cone_of(int cx, int cy) {
  const uint32_t h1 = lattice_hash(cx, cy, 0, kGroundConeSalt), h2 = lattice_hash(cx, cy, 1, kGroundConeSalt);
  const auto byte = [](uint32_t h, int shift) { return float((h >> shift) & 255u) / 255.0f; };
  const float ax = byte(h1, 16) * 2.0f - 1.0f, ay = byte(h1, 24) * 2.0f - 1.0f, len = std::sqrt(ax * ax + ay * ay + 1e-8f);
  return {byte(h2, 24) < kSpruceConeShare, byte(h2, 8), kSpruceConeHalf[0] + kSpruceConeHalf[1] * byte(h2, 0),
          (float(cx) + byte(h1, 0)) * kSpruceConeCell, (float(cy) + byte(h1, 8)) * kSpruceConeCell, ax / len, ay / len};
}

/// True when `c` is a cone's colour (its hue's mix of dark and light) times `shade`, to 1e-5.
bool cone_colour(const Vec3f& c, float hue, float shade) {
  bool same = true;
  for (int k = 0; k < 3; ++k) same = same && std::abs(c[k] - mix(kSpruceConeDark[k], kSpruceConeLight[k], hue) * shade) < 1e-5f;
  return same;
}

TEST(SpruceCones, FullSizeConesLieWhereSpruceNeedlesLie) {
  // Known answers from the hashes: a kept cone's centre lies on both seams (its colour x (1 - kLitterConeSeam)),
  // it reaches 90 % of its half length along its axis and not past it, and with no spruce needles the
  // floor stays bare.
  int cones = 0, centred = 0, long_enough = 0, not_longer = 0;
  for (int cy = 0; cy < 40; ++cy)
    for (int cx = -20; cx < 20; ++cx) {
      const Cone k = cone_of(cx, cy);
      EXPECT_EQ(cones_at(k.x, k.y, 0.0f), kFloor);
      if (!k.kept) continue;
      ++cones;
      EXPECT_GE(2.0f * k.half_length, 0.1f);  // Picea abies: 10-16 cm
      EXPECT_LE(2.0f * k.half_length, 0.16f + 1e-6f);
      centred += cone_colour(cones_at(k.x, k.y, 1.0f), k.hue, 1.0f - kLitterConeSeam);
      const float in = 0.9f * k.half_length, out = k.half_length + 1.5f * kSpruceConeReach;
      long_enough += cones_at(k.x + in * k.ux, k.y + in * k.uy, 1.0f) != kFloor;
      not_longer += cones_at(k.x + out * k.ux, k.y + out * k.uy, 1.0f) == kFloor;
    }
  const float per_m2 = float(cones) / (1600.0f * kSpruceConeCell * kSpruceConeCell);
  EXPECT_GT(per_m2, 3.5f);  // about five per square metre under spruce
  EXPECT_LT(per_m2, 6.5f);
  EXPECT_GT(centred, cones * 8 / 10);  // the rest overlapped by a neighbour
  EXPECT_GT(long_enough, cones * 9 / 10);
  EXPECT_GT(not_longer, cones * 8 / 10);
}

TEST(SpruceCones, HalfTheSpruceNeedlesHoldAboutHalfTheCones) {
  int full = 0, half = 0;
  for (int cy = 0; cy < 60; ++cy)
    for (int cx = 0; cx < 60; ++cx) {
      const Cone k = cone_of(cx, cy);
      full += cones_at(k.x, k.y, 1.0f) != kFloor;
      half += cones_at(k.x, k.y, 0.5f) != kFloor;
    }
  EXPECT_GT(half, full * 4 / 10);
  EXPECT_LT(half, full * 6 / 10);
}

TEST(SpruceCones, TheyFadeOutWithTheFootprintAndLieOnlyWithWeight) {
  EXPECT_EQ(spruce_cone_fade(0.0f), 1.0f);
  EXPECT_EQ(spruce_cone_fade(kSpruceConeFadeNear), 1.0f);
  EXPECT_EQ(spruce_cone_fade(kSpruceConeFadeFar), 0.0f);
  EXPECT_GT(spruce_cone_fade(0.03f), spruce_cone_fade(0.045f));
  EXPECT_GT(kSpruceConeFadeFar, kLitterFadeFar);  // seen beyond the small litter: 10 cm and more long
  for (int cy = 0; cy < 10; ++cy)
    for (int cx = 0; cx < 10; ++cx) {
      const Cone k = cone_of(cx, cy);
      EXPECT_EQ(cones_at(k.x, k.y, 1.0f, 0.0f), kFloor);
      EXPECT_EQ(cones_at(k.x, k.y, 1.0f, spruce_cone_fade(0.06f), 0.06f), kFloor);
    }
}

TEST(SpruceCones, TheFilterKeepsTheMeanColour) {
  // Antialiased over a pixel's box: a 4 cm pixel spreads each cone but keeps most of its colour (the seams and
  // contact shadows, far thinner than the pixel, fade into the cone's mean).
  const auto mean_green = [](float footprint) {
    double sum = 0.0;
    for (int j = 0; j < 400; ++j)
      for (int i = 0; i < 400; ++i) sum += cones_at(3.0f + 0.005f * float(i), -1.0f + 0.005f * float(j), 1.0f, 1.0f, footprint).y();
    return sum / 160000.0;
  };
  const double sharp = mean_green(1e-4f), soft = mean_green(0.04f);
  EXPECT_LT(sharp, double(kFloor.y()) - 0.0005);  // the cones and their shadows darken the mean
  EXPECT_NEAR(soft, sharp, 0.25 * (double(kFloor.y()) - sharp));
}

}  // namespace
}  // namespace silva::render
