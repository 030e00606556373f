// Botanical-scale foliage masks: card-size classes, mask sizes, coverage, leaf lengths, and the
// stroke rasteriser they rely on.
#include "assets/foliage_sprays.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>

#include "assets/species.hpp"
#include "core/rng.hpp"

namespace silva::assets {
namespace {

/// A species' spray family, its target coverage and the botanical range of its leaf or needle length (m).
struct Family {
  const char* name;
  MaskFamily family;
  double coverage;
  double min_m, max_m;
};

const Family kFamilies[] = {{"spruce", spruce_spray, 0.26, 0.010, 0.025}, {"pine", pine_spray, 0.18, 0.03, 0.07},
                            {"larch", larch_spray, 0.15, 0.02, 0.04},     {"beech", beech_spray, 0.37, 0.05, 0.10},
                            {"birch", birch_spray, 0.21, 0.03, 0.07},     {"oak", oak_spray, 0.25, 0.07, 0.14}};

double coverage(const AlphaMask& m) {
  return double(std::count_if(m.alpha.begin(), m.alpha.end(), [](uint8_t a) { return a >= 128; })) /
         double(m.alpha.size());
}

TEST(FoliageSprays, ClassIsTheNearestSideInRatio) {
  EXPECT_EQ(spray_class(0.25f), 0);
  EXPECT_EQ(spray_class(0.01f), 0);
  EXPECT_EQ(spray_class(0.35f), 0);  // log2(1.4) = 0.49
  EXPECT_EQ(spray_class(0.36f), 1);
  EXPECT_EQ(spray_class(0.7f), 1);
  EXPECT_EQ(spray_class(1.0f), 2);
  EXPECT_EQ(spray_class(1.5f), 3);
  EXPECT_EQ(spray_class(40.0f), kSprayClasses - 1);
}

TEST(FoliageSprays, EveryClassIsSquareWithLeafShadesAndCoversItsTarget) {
  for (const Family& f : kFamilies) {
    for (int k = 0; k < kSprayClasses; ++k) {
      const float side = kSprayClassSide * float(1 << k);
      SCOPED_TRACE(std::string(f.name) + " " + std::to_string(side));
      const auto mask = f.family(side);
      ASSERT_EQ(mask->width, mask->height);
      EXPECT_TRUE(std::has_single_bit(unsigned(mask->width)));
      EXPECT_GE(mask->width, 256);
      EXPECT_LE(mask->width, 1024);
      bool seen[256] = {};
      for (uint8_t a : mask->alpha) {
        ASSERT_TRUE(a == 0 || a >= 128);  // transparent, or opaque with a leaf's brightness (255: twig)
        seen[a] = true;
      }
      EXPECT_TRUE(seen[255]);
      EXPECT_GE(std::count(seen + 128, seen + 255, true), k == 0 ? 3 : k == 1 ? 10 : 40);  // leaves differ
      EXPECT_NEAR(coverage(*mask), f.coverage, 0.03);
      EXPECT_FALSE(mask->opaque(0.02f, 0.02f));  // corners stay empty: the spray is no square
      EXPECT_FALSE(mask->opaque(0.98f, 0.02f));
    }
  }
}

TEST(FoliageSprays, LeavesHaveTheirBotanicalLengthOnEveryCardSize) {
  for (const Family& f : kFamilies) {
    for (int k = 0; k < kSprayClasses; ++k) {
      const float side = kSprayClassSide * float(1 << k);
      SCOPED_TRACE(std::string(f.name) + " " + std::to_string(side));
      const auto mask = f.family(side);
      const double metres = double(mask->feature_length) * double(side);
      EXPECT_GE(metres, f.min_m);
      EXPECT_LE(metres, f.max_m);
      // A leaf is at least 12 texels long unless the mask has reached its largest size.
      EXPECT_TRUE(mask->feature_length * float(mask->width) >= 12.0f || mask->width == 1024);
    }
  }
}

TEST(FoliageSprays, CardsOfOneClassShareAMaskAndClassesDiffer) {
  EXPECT_EQ(beech_spray(0.9f), beech_spray(1.1f));
  EXPECT_NE(beech_spray(0.5f), beech_spray(1.0f));
  EXPECT_NE(beech_spray(1.0f), oak_spray(1.0f));
}

TEST(FoliageSprays, DrawingIsDeterministic) {
  const SprayLeaf leaf{.length_m = 0.06f, .coverage = 0.3f};
  EXPECT_EQ(draw_spray(leaf, 1.0f, 9)->alpha, draw_spray(leaf, 1.0f, 9)->alpha);
  EXPECT_NE(draw_spray(leaf, 1.0f, 9)->alpha, draw_spray(leaf, 1.0f, 10)->alpha);
}

TEST(FoliageSprays, SpeciesCardsCarryTheirFamily) {
  EXPECT_EQ(norway_spruce().look.cards.family, &spruce_spray);
  EXPECT_EQ(european_beech().look.cards.family, &beech_spray);
  EXPECT_EQ(common_oak().look.cards.family, &oak_spray);
}

TEST(FoliageSprays, BareTwigsMatchTheCardSizeOfTheLeavesTheyReplace) {
  for (int k = 0; k < kSprayClasses; ++k) {
    const float side = kSprayClassSide * float(1 << k);
    for (const MaskFamily leafy : {&beech_spray, &birch_spray, &oak_spray, &larch_spray})
      EXPECT_EQ(bare_twigs_for(leafy(side).get()), bare_twig_spray(side)) << side;
    const auto twigs = bare_twig_spray(side);
    EXPECT_NEAR(coverage(*twigs), 0.1, 0.03) << side;
    EXPECT_TRUE(std::all_of(twigs->alpha.begin(), twigs->alpha.end(), [](uint8_t a) { return a == 0 || a == 255; }));
  }
  EXPECT_EQ(bare_twigs_for(spruce_spray(1.0f).get()), nullptr);  // evergreens keep their needles
  EXPECT_EQ(bare_twigs_for(nullptr), nullptr);
}

TEST(MaskStrokes, AStrokeCoversItsLengthInTexels) {
  // Half-width 0.02 (5.12 texels) along y = 0.5 from x = 0.25 to 0.75 on 256 texels, with round ends: the
  // middle rows 127 and 128 (centres 0.002 off the axis) are opaque from texel 59 to 196.
  const auto mask = rasterise_strokes({{{0.25f, 0.5f}, {0.75f, 0.5f}, 0.02f, 0.02f}}, 256, 256);
  for (int y : {127, 128}) {
    for (int x = 0; x < 256; ++x)
      EXPECT_EQ(mask->alpha[size_t(y) * 256 + size_t(x)] == 255, x >= 59 && x <= 196) << x << "," << y;
  }
  EXPECT_NEAR(coverage(*mask), 0.5 * 0.04 + 3.14159 * 0.02 * 0.02, 0.001);  // the stadium's area
}

TEST(MaskStrokes, EqualsTheTestOfEveryTexelAgainstEveryStroke) {
  Rng rng(5, 1, Purpose::Test);
  std::vector<Stroke> strokes;
  for (int i = 0; i < 40; ++i) {
    const Vec2f a(rng.range(-0.1f, 1.1f), rng.range(-0.1f, 0.6f));
    const auto shape = Stroke::Shape(i % 3);
    strokes.push_back({a, a + Vec2f(rng.range(-0.3f, 0.3f), rng.range(-0.3f, 0.3f)), rng.range(0.002f, 0.05f),
                       rng.range(0.0f, 0.03f), shape});
  }
  const int w = 96, h = 48;
  const auto mask = rasterise_strokes(strokes, w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Vec2f p((float(x) + 0.5f) / float(w), (float(y) + 0.5f) / float(w));
      const bool any = std::any_of(strokes.begin(), strokes.end(), [&](const Stroke& s) { return stroke_covers(s, p); });
      ASSERT_EQ(mask->alpha[size_t(y) * size_t(w) + size_t(x)] == 255, any) << x << "," << y;
    }
}

}  // namespace
}  // namespace silva::assets
