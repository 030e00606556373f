#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/value_noise.hpp"
#include "render/floor_litter.hpp"
#include "render/noise_salts.hpp"

namespace silva::render {
namespace {

const Vec3f kFloor(0.1f, 0.1f, 0.1f);  ///< A grey floor under the sprites.

/// The floor colour after the sprites at (x, y).
Vec3f litter_at(float x, float y, float footprint, float needles, float weight = 1.0f, Vec2f* slope = nullptr,
                float grass = 0.0f) {
  Vec3f c = kFloor;
  Vec2f s(0.0f, 0.0f);
  litter_sprites(x, y, footprint, {grass, needles, 0.0f}, weight, c, s);
  if (slope) *slope = s;
  return c;
}

/// Share of a 1 m square's points (5 mm apart) that the sprites change, at a 2 mm footprint; `greener`
/// (if set) receives the share of the points coloured by a sprite whose green exceeds their red.
float covered_share(float needles, float grass = 0.0f, float* greener = nullptr) {
  int changed = 0, green = 0, coloured = 0, total = 0;
  for (int j = 0; j < 200; ++j)
    for (int i = 0; i < 200; ++i, ++total) {
      const Vec3f c = litter_at(3.0f + 0.005f * float(i), -2.0f + 0.005f * float(j), 0.002f, needles, 1.0f, nullptr, grass);
      changed += (c - kFloor).norm() > 0.01f;
      green += c.y() > c.x();
      coloured += c.maxCoeff() - c.minCoeff() > 0.005f;  // a sprite, not only its shadow on the grey floor
    }
  if (greener) *greener = float(green) / float(std::max(coloured, 1));
  return float(changed) / float(total);
}

TEST(FloorLitter, LeavesCoverPartOfABroadleafFloorAndNeedlesLess) {
  const float leaves = covered_share(0.0f), needles = covered_share(1.0f);
  EXPECT_GT(leaves, 0.35f);  // single leaves with the dark floor between them
  EXPECT_LT(leaves, 0.8f);
  EXPECT_GT(needles, 0.03f);  // thin needles and a few twigs
  EXPECT_LT(needles, 0.5f * leaves);
}

TEST(FloorLitter, OnGrassMostSpritesAreGreenBlades) {
  float litter_green = 1.0f, grass_green = 0.0f;
  covered_share(0.0f, 0.0f, &litter_green);
  const float blades = covered_share(0.0f, 1.0f, &grass_green);
  EXPECT_LT(litter_green, 0.01f);  // leaves are brown
  EXPECT_GT(grass_green, 0.6f);    // blades; twigs (wider) aside
  EXPECT_GT(blades, 0.05f);
}

TEST(FloorLitter, NoWeightOrAFarFootprintLeavesTheFloorAlone) {
  for (int i = 0; i < 500; ++i) {
    const float x = 0.0137f * float(i), y = 0.0071f * float(i);
    EXPECT_EQ(litter_at(x, y, 0.002f, 0.0f, 0.0f), kFloor);
    EXPECT_EQ(litter_at(x, y, 0.002f, 0.0f, litter_fade(0.04f)), kFloor);
  }
  EXPECT_EQ(litter_fade(0.0f), 1.0f);
  EXPECT_EQ(litter_fade(kLitterFadeNear), 1.0f);
  EXPECT_EQ(litter_fade(kLitterFadeFar), 0.0f);
  EXPECT_GT(litter_fade(0.015f), litter_fade(0.025f));
}

/// A top-layer cell's sprite as its hashes draw it: whether it is kept, its kind and hue draws and its
/// centre (metres).
struct TopSprite {
  bool kept;
  float kind, hue, x, y;
};

TopSprite top_sprite(int cx, int cy) {
  const int32_t top = 2 * (kLitterLayers - 1);
  const uint32_t h1 = lattice_hash(cx, cy, top, kGroundLitterSalt), h2 = lattice_hash(cx, cy, top + 1, kGroundLitterSalt);
  return {float(h2 >> 24) / 255.0f < kLitterDensity, float((h2 >> 16) & 255u) / 255.0f, float((h2 >> 8) & 255u) / 255.0f,
          (float(cx) + float(h1 & 255u) / 255.0f) * kLitterCell, (float(cy) + float((h1 >> 8) & 255u) / 255.0f) * kLitterCell};
}

/// True when `c` is the mix of `dark` and `light` by `hue`, times `shade`, to 1e-5 in every channel.
bool has_colour(const Vec3f& c, const float* dark, const float* light, float hue, float shade) {
  bool same = true;
  for (int k = 0; k < 3; ++k) same = same && std::abs(c[k] - mix(dark[k], light[k], hue) * shade) < 1e-5f;
  return same;
}

TEST(FloorLitter, ALeafCentreHasItsLeafsColourFromTheCellHash) {
  // Known answer from the hashes alone: a kept leaf of the top layer has its centre on its midrib (colour
  // x (1 - kLitterRib)) unless a sprite of a later cell of that layer lies over it.
  int leaves = 0, matched = 0;
  for (int cy = 40; cy < 60; ++cy)
    for (int cx = -10; cx < 10; ++cx) {
      const TopSprite t = top_sprite(cx, cy);
      if (!t.kept || t.kind >= 1.0f - kLitterTwigShare) continue;
      ++leaves;
      matched += has_colour(litter_at(t.x, t.y, 1e-4f, 0.0f), kLitterLeafDark, kLitterLeafLight, t.hue, 1.0f - kLitterRib);
    }
  EXPECT_GT(leaves, 300);
  EXPECT_GT(matched, leaves / 2);
}

TEST(FloorLitter, ConesLieOnlyUnderConifersWithSeamsAtTheirCentre) {
  // Known answer from the hashes: where the needle share is 1, a kept sprite of the top layer whose kind
  // falls in the cone band is a cone, and its centre lies on both seams (colour x (1 - kLitterConeSeam))
  // unless a later sprite of that layer covers it; with no needles the same cells hold no cone.
  int cones = 0, matched = 0, broadleaf_cones = 0;
  const float untwigged = 1.0f - kLitterTwigShare, shade = 1.0f - kLitterConeSeam;
  for (int cy = 0; cy < 60; ++cy)
    for (int cx = -30; cx < 30; ++cx) {
      const TopSprite t = top_sprite(cx, cy);
      if (!t.kept || t.kind >= untwigged || t.kind < untwigged - kLitterConeShare) continue;
      ++cones;
      matched += has_colour(litter_at(t.x, t.y, 1e-4f, 1.0f), kLitterConeDark, kLitterConeLight, t.hue, shade);
      broadleaf_cones += has_colour(litter_at(t.x, t.y, 1e-4f, 0.0f), kLitterConeDark, kLitterConeLight, t.hue, shade);
    }
  EXPECT_GT(cones, 40);  // 2 % of 3 600 cells
  EXPECT_GT(matched, cones / 2);
  EXPECT_EQ(broadleaf_cones, 0);
}

/// Largest colour change between points 1 mm apart along a 1 m line, and the range along it.
void steps_along_a_line(float footprint, float& largest_step, float& range) {
  largest_step = 0.0f;
  float lo = 1.0f, hi = 0.0f;
  float previous = litter_at(5.0f, 1.234f, footprint, 0.0f).x();
  for (int i = 1; i < 1000; ++i) {
    const float r = litter_at(5.0f + 0.001f * float(i), 1.234f, footprint, 0.0f).x();
    largest_step = std::max(largest_step, std::abs(r - previous));
    lo = std::min(lo, r);
    hi = std::max(hi, r);
    previous = r;
  }
  range = hi - lo;
}

TEST(FloorLitter, EdgesAreAntialiasedOverThePixelsFootprint) {
  float sharp_step = 0.0f, sharp_range = 0.0f, soft_step = 0.0f, soft_range = 0.0f;
  steps_along_a_line(1e-4f, sharp_step, sharp_range);  // a pixel far smaller than the 1 mm spacing: hard edges
  steps_along_a_line(0.01f, soft_step, soft_range);    // 1 cm pixels: an edge takes ten steps
  EXPECT_GT(sharp_step, 0.5f * sharp_range);
  EXPECT_GT(soft_range, 0.3f * sharp_range);
  EXPECT_LT(soft_step, 0.3f * soft_range);
}

TEST(FloorLitter, TheFilterKeepsTheMeanColour) {
  // A box filter moves ink around but keeps its amount: the mean over a patch barely depends on the footprint.
  const auto mean_red = [](float footprint) {
    double sum = 0.0;
    for (int j = 0; j < 300; ++j)
      for (int i = 0; i < 300; ++i) sum += litter_at(-4.0f + 0.002f * float(i), 7.0f + 0.002f * float(j), footprint, 0.0f).x();
    return sum / 90000.0;
  };
  const double fine = mean_red(1e-4f), coarse = mean_red(0.015f);
  EXPECT_NEAR(coarse, fine, 0.08 * (fine - double(kFloor.x())) + 0.002);
}

TEST(FloorLitter, SpritesTiltTheReliefWithinTheirLimit) {
  float steepest = 0.0f;
  for (int i = 0; i < 2000; ++i) {
    Vec2f slope;
    litter_at(0.0031f * float(i), 0.5f, 0.001f, 0.0f, 1.0f, &slope);
    steepest = std::max(steepest, slope.norm());
  }
  const float limit = std::hypot(kLitterTilt, kLitterCurl);  // tilted along the leaf, curled across it
  EXPECT_GT(steepest, 0.5f * limit);
  EXPECT_LE(steepest, limit * 1.0001f);
  // Under conifers the cones' round flanks are steeper than any leaf, within their own limit.
  float steepest_cone = 0.0f;
  for (int j = 0; j < 100; ++j)
    for (int i = 0; i < 400; ++i) {
      Vec2f slope;
      litter_at(0.0025f * float(i), 0.01f * float(j), 0.0005f, 1.0f, 1.0f, &slope);
      steepest_cone = std::max(steepest_cone, slope.norm());
    }
  EXPECT_GT(steepest_cone, limit * 1.2f);
  EXPECT_LE(steepest_cone, std::hypot(kLitterTilt, kLitterConeRound) * 1.0001f);
}

}  // namespace
}  // namespace silva::render
