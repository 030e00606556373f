// Known answers of the understory and forest-floor generators.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "assets/factory.hpp"
#include "assets/generators.hpp"
#include "assets/rock_shape.hpp"
#include "assets/understory_masks.hpp"

namespace silva::assets {
namespace {

const Factory& factory(const char* prefix) {
  const Factory* f = find_factory(prefix);
  if (f == nullptr) throw std::runtime_error(prefix);
  return *f;
}

/// Opaque texels of one mask row.
int row_count(const AlphaMask& m, int y) {
  int n = 0;
  for (int x = 0; x < m.width; ++x) n += m.alpha[size_t(y * m.width + x)] != 0;
  return n;
}

TEST(Understory, FernsHaveFiveToTwelvePinnateFronds) {
  const Factory& f = factory("fern");
  std::set<size_t> counts;
  for (uint32_t v = 0; v < f.variants; ++v) {
    const Asset a = make_asset(f, kDefaultAssetSeed, v);
    const Mesh& m = a.lods()[0];
    ASSERT_EQ(m.parts.size(), 1u);
    EXPECT_EQ(m.parts[0].mask, pinnate_frond_mask());
    const size_t fronds = m.parts[0].index_count / (6 * kFrondSegments);
    EXPECT_EQ(fronds * 6 * kFrondSegments, m.parts[0].index_count);
    EXPECT_GE(fronds, 5u);
    EXPECT_LE(fronds, 12u);
    counts.insert(fronds);
  }
  EXPECT_GE(counts.size(), 3u);  // the rosette size varies
}

TEST(Understory, FernLeafletsArePairedAndTheFrondTapers) {
  const AlphaMask& m = *pinnate_frond_mask();
  ASSERT_EQ(m.width, kFrondMaskWidth);
  ASSERT_EQ(m.height, kFrondMaskHeight);
  size_t opaque = 0, mirrored = 0;
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x)
      if (m.alpha[size_t(y * m.width + x)]) {
        ++opaque;
        mirrored += m.alpha[size_t(y * m.width + m.width - 1 - x)] != 0;
      }
  EXPECT_GT(double(mirrored), 0.98 * double(opaque));  // every pinna has its partner
  EXPECT_LE(row_count(m, m.height - 4), 4);             // bare stipe at the base
  EXPECT_GT(row_count(m, m.height / 2), 30);            // wide pinnae mid-frond
  EXPECT_LT(row_count(m, 6), row_count(m, m.height / 2) / 2);  // tapering tip
  // Pinnae come in rows with gaps between them: along the edge, coverage switches on and off.
  int switches = 0;
  for (int y = 1; y < m.height; ++y) switches += (m.alpha[size_t(y * m.width + 14)] != 0) != (m.alpha[size_t((y - 1) * m.width + 14)] != 0);
  EXPECT_GE(switches, 16);
}

TEST(Understory, RockDisplacementIsBoundedAndNotASphere) {
  for (uint64_t key = 0; key < 8; ++key) {
    Rng rng(3, key, Purpose::Test);
    const RockShape shape = random_rock_shape(rng);
    Rng dirs(4, key, Purpose::Test);
    float lo = 10, hi = 0;
    for (int i = 0; i < 500; ++i) {
      const float r = shape.radius(random_direction(dirs));
      lo = std::min(lo, r);
      hi = std::max(hi, r);
    }
    EXPECT_GE(lo, kRockMinRadius);
    EXPECT_LE(hi, kRockMaxRadius);
    EXPECT_GT(hi - lo, 0.15f) << key;
  }
}

TEST(Understory, LogEndsAreJagged) {
  const Factory& f = factory("log");
  int jagged_ends = 0;
  for (uint32_t v = 0; v < f.variants; ++v) {
    const Asset a = make_asset(f, kDefaultAssetSeed, v);
    const Mesh& m = a.lods()[0];
    const MeshPart& ends = m.parts.back();
    ASSERT_EQ(ends.material, Material::BrokenWood);
    for (float side : {-1.0f, 1.0f}) {
      float lo = 1e9f, hi = -1e9f;
      for (uint32_t i = ends.first_index; i < ends.first_index + ends.index_count; ++i) {
        const float x = m.positions[m.indices[i]].x();
        if (x * side <= 0) continue;
        lo = std::min(lo, x * side);
        hi = std::max(hi, x * side);
      }
      jagged_ends += hi - lo > 0.03f;
    }
  }
  EXPECT_GE(jagged_ends, int(f.variants));  // most of the 2 x variants ends are broken
}

TEST(Understory, StumpsFlareAtTheBase) {
  const Factory& f = factory("stump");
  for (uint32_t v = 0; v < 6; ++v) {
    const Asset a = make_asset(f, kDefaultAssetSeed, v);
    const Mesh& m = a.lods()[0];
    float base = 0, top = 0;
    const float h = m.bounds().max.z();
    for (const Vec3f& p : m.positions) {
      const float r = p.head<2>().norm();
      if (p.z() < 0.02f) base = std::max(base, r);
      if (p.z() > 0.6f * h) top = std::max(top, r);
    }
    EXPECT_GT(base, 1.3f * top) << v;
  }
}

TEST(Understory, ThinStemsAreRibbonsNotTubes) {
  for (const char* prefix : {"bilberry", "hazel", "bramble", "twig"}) {
    const Asset a = make_asset(factory(prefix), 2, 0);
    const Mesh& m = a.lods()[0];
    for (const MeshPart& p : m.parts)
      if (!p.mask && !p.double_sided) {  // a tube part: every ring is at least kMinTubeRadius thick
        for (uint32_t i = p.first_index; i < p.first_index + p.index_count; i += 3) {
          const Vec3f& a = m.positions[m.indices[i]];
          const Vec3f& b = m.positions[m.indices[i + 1]];
          EXPECT_GT((a - b).norm(), 0.005f) << prefix;
        }
      }
  }
}

/// Spans (metres) of the leaves of a herb mesh's card part whose leaves span `fill` of their card's side, and
/// the heights of their centres.
void herb_leaves(const Mesh& m, const MeshPart& cards, float fill, std::vector<float>& spans, std::vector<float>& heights) {
  for (uint32_t i = cards.first_index; i < cards.first_index + cards.index_count; i += 6) {
    float diagonal = 0;
    Vec3f centre = Vec3f::Zero();
    for (uint32_t a = i; a < i + 6; ++a) {
      centre += m.positions[m.indices[a]] / 6.0f;
      for (uint32_t b = i; b < i + 6; ++b)
        diagonal = std::max(diagonal, (m.positions[m.indices[a]] - m.positions[m.indices[b]]).norm());
    }
    spans.push_back(diagonal / std::sqrt(2.0f) * fill);
    heights.push_back(centre.z());
  }
}

/// Expects every height in (lo, hi) metres: leaves held up on their stems, never lying in the litter.
void expect_heights(const std::vector<float>& heights, float lo, float hi, const std::string& name) {
  for (float h : heights) {
    EXPECT_GT(h, lo) << name;
    EXPECT_LT(h, hi) << name;
  }
}

/// Expects every span within [lo, hi] metres and their median within (median_lo, median_hi).
void expect_spans(std::vector<float> spans, float lo, float hi, float median_lo, float median_hi) {
  ASSERT_FALSE(spans.empty());
  std::sort(spans.begin(), spans.end());
  EXPECT_GE(spans.front(), lo);
  EXPECT_LE(spans.back(), hi);
  EXPECT_GT(spans[spans.size() / 2], median_lo);
  EXPECT_LT(spans[spans.size() / 2], median_hi);
}

/// Whether the texel of a square mask at angle `deg` (0 = up the mask) and `r` mask units from its centre is opaque.
bool opaque_at(const AlphaMask& m, float deg, float r) {
  const float a = deg * 3.14159265f / 180.0f;
  const int x = int((0.5f + r * std::sin(a)) * float(m.width)), y = int((0.5f - r * std::cos(a)) * float(m.height));
  return m.alpha[size_t(y * m.width + x)] != 0;
}

/// Separate opaque runs on the circle `r` mask units round a square mask's centre, sampled every 3 degrees.
int leaves_round(const AlphaMask& m, float r) {
  int leaves = 0;
  for (int deg = 0; deg < 360; deg += 3) leaves += opaque_at(m, float(deg), r) && !opaque_at(m, float(deg) - 3.0f, r);
  return leaves;
}

TEST(Understory, WoodSorrelCarpetsLowLeavesOfBotanicalSize) {
  std::vector<float> spans;
  for (uint32_t v = 0; v < factory("wood_sorrel").variants; ++v) {
    const Asset a = make_asset(factory("wood_sorrel"), kDefaultAssetSeed, v);
    const Mesh& m = a.lods()[0];
    EXPECT_EQ(a.role, Role::GroundVegetation);
    EXPECT_EQ(a.proxy.shape, CollisionProxy::Shape::None);
    EXPECT_EQ(a.lods().size(), 1u);
    EXPECT_LE(m.triangle_count(), 320u) << a.name;
    std::vector<float> heights;
    for (const MeshPart& p : m.parts) {
      EXPECT_EQ(p.role, Role::GroundVegetation);
      EXPECT_EQ(p.material, Material::Herb);
      ASSERT_TRUE(p.mask == wood_sorrel_leaf_mask() || p.mask == herb_stalk_mask());  // cards only: one level
      if (p.mask == wood_sorrel_leaf_mask()) herb_leaves(m, p, kWoodSorrelLeafFill, spans, heights);
    }
    EXPECT_GE(heights.size(), size_t(kMinWoodSorrelLeaves)) << a.name;
    EXPECT_LE(heights.size(), 80u) << a.name;
    expect_heights(heights, 0.015f, 0.15f, a.name);
  }
  expect_spans(spans, 0.02f, 0.051f, 0.03f, 0.04f);  // Oxalis acetosella: leaflets 1-2 cm long, a leaf 2-4.5 cm across
}

TEST(Understory, WoodSorrelLeavesAreThreeNotchedLeaflets) {
  const AlphaMask& m = *wood_sorrel_leaf_mask();
  ASSERT_EQ(m.width, kWoodSorrelMaskSize);
  ASSERT_EQ(m.height, kWoodSorrelMaskSize);
  const auto opaque = [&](float deg, float r) { return opaque_at(m, deg, r); };
  for (int i = 0; i < 3; ++i) {
    const float axis = 120.0f * float(i) + 8.0f;
    EXPECT_TRUE(opaque(axis, 0.2f)) << i;          // the leaflet's body
    EXPECT_TRUE(opaque(axis - 19.0f, 0.33f)) << i;  // both lobes
    EXPECT_TRUE(opaque(axis + 19.0f, 0.33f)) << i;
    EXPECT_FALSE(opaque(axis, 0.42f)) << i;         // the notch between them at the tip
    EXPECT_FALSE(opaque(axis + 60.0f, 0.3f)) << i;  // the gap to the next leaflet
  }
}

/// How a stemmed herb's patches must grow: stems per patch, leaf levels per stem, leaf heights (m).
struct StemmedHerb {
  const char* prefix;
  std::shared_ptr<const AlphaMask> leaf_mask;
  float fill;                      ///< Share of its card's side a leaf level spans.
  size_t min_stems, max_stems;
  size_t min_levels, max_levels;
  float lowest, highest;           ///< Range every leaf level's height lies in.
  std::shared_ptr<const AlphaMask> flower_mask = nullptr;  ///< Mask of a third, flower part (null: none).
};

/// Share of its card's side a flower spans (the flower masks reach 0.46 from the centre).
constexpr float kFlowerFill = 0.92f;

/// The flowers of every variant of a herb.
struct FlowerCounts {
  std::vector<float> spans, heights;  ///< Every flower's span and height, metres.
  size_t stems = 0;                   ///< Stems of every variant.
};

/// Checks every variant of `herb` (a stalk part, a leaf part and the flower part it has, levels up every stem,
/// heights in range); returns the spans of all their leaf levels and, per variant, the highest level's height.
/// Adds the flowers' spans, heights and the variants' stems to `flowers` when the herb has flowers.
std::vector<float> stemmed_herb_spans(const StemmedHerb& herb, std::vector<float>& tops, FlowerCounts* flowers = nullptr) {
  std::vector<float> spans;
  const size_t parts = herb.flower_mask ? 3 : 2;
  for (uint32_t v = 0; v < factory(herb.prefix).variants; ++v) {
    const Asset a = make_asset(factory(herb.prefix), kDefaultAssetSeed, v);
    const Mesh& m = a.lods()[0];
    EXPECT_EQ(a.lods().size(), 1u);
    EXPECT_EQ(m.parts.size(), parts) << a.name;
    if (m.parts.size() != parts) continue;
    EXPECT_EQ(m.parts[0].mask, herb_stalk_mask());
    EXPECT_EQ(m.parts[1].mask, herb.leaf_mask);
    if (flowers) {
      EXPECT_EQ(m.parts[2].mask, herb.flower_mask);
      EXPECT_EQ(m.parts[2].material, Material::Petals);
      herb_leaves(m, m.parts[2], kFlowerFill, flowers->spans, flowers->heights);
      flowers->stems += m.parts[0].index_count / 6;
    }
    const size_t stems = m.parts[0].index_count / 6;
    EXPECT_GE(stems, herb.min_stems) << a.name;
    EXPECT_LE(stems, herb.max_stems) << a.name;
    std::vector<float> heights;
    herb_leaves(m, m.parts[1], herb.fill, spans, heights);
    EXPECT_GE(heights.size(), herb.min_levels * stems) << a.name;
    EXPECT_LE(heights.size(), herb.max_levels * stems) << a.name;
    expect_heights(heights, herb.lowest, herb.highest, a.name);
    tops.push_back(heights.empty() ? 0.0f : *std::max_element(heights.begin(), heights.end()));
  }
  return spans;
}

TEST(Understory, WoodruffStemsCarryWhorlsOfBotanicalSize) {
  std::vector<float> tops;  // three or four whorls up every stem
  const StemmedHerb woodruff{"woodruff", woodruff_whorl_mask(), kWoodruffWhorlFill, kMinWoodruffStems, 36, 3, 4, 0.02f, 0.3f};
  // Galium odoratum: leaves 2-5 cm long, so a whorl 4-10 cm across (the top whorl smaller).
  expect_spans(stemmed_herb_spans(woodruff, tops), 0.025f, 0.1f, 0.045f, 0.08f);
}

TEST(Understory, WoodruffWhorlsAreEightNarrowLeaves) {
  const AlphaMask& m = *woodruff_whorl_mask();
  ASSERT_EQ(m.width, kWoodruffMaskSize);
  const auto opaque = [&](float deg, float r) { return opaque_at(m, deg, r); };
  EXPECT_EQ(leaves_round(m, 0.3f), kWoodruffWhorlLeaves);  // separate leaves round the stem, 0.3 of the side out
  int covered = 0;
  for (int deg = 0; deg < 360; deg += 3) covered += opaque(float(deg), 0.3f);
  EXPECT_LT(covered, 60);  // narrow: under half the circle is leaf
}

TEST(Understory, WoodAnemoneStemsCarryALeafWhorlAndMostAFlowerOfBotanicalSize) {
  std::vector<float> tops;  // one whorl up every stem
  FlowerCounts flowers;
  const StemmedHerb anemone{"wood_anemone", wood_anemone_whorl_mask(), kWoodAnemoneWhorlFill, kMinWoodAnemoneStems, 50,
                            1, 1, 0.02f, 0.25f, wood_anemone_flower_mask()};
  // Anemone nemorosa: three stem leaves 3-6 cm long, so a whorl 6-12 cm across (smaller and larger plants beside).
  expect_spans(stemmed_herb_spans(anemone, tops, &flowers), 0.05f, 0.135f, 0.075f, 0.095f);
  // One white flower 2-4 cm across (a few to 4.5) on most stems, above the leaves.
  expect_spans(flowers.spans, 0.017f, 0.046f, 0.026f, 0.034f);
  const double share = double(flowers.spans.size()) / double(flowers.stems);
  EXPECT_GT(share, 0.65);
  EXPECT_LT(share, 0.85);
  expect_heights(flowers.heights, 0.03f, 0.26f, "wood_anemone flowers");
  std::sort(tops.begin(), tops.end());
  std::sort(flowers.heights.begin(), flowers.heights.end());
  EXPECT_GT(flowers.heights[flowers.heights.size() / 2], 0.9f * tops[0]);  // flowers stand over the whorls
}

TEST(Understory, WoodAnemoneWhorlsAreThreeCutLeavesAndFlowersSixTepals) {
  const AlphaMask& whorl = *wood_anemone_whorl_mask();
  ASSERT_EQ(whorl.width, kWoodAnemoneMaskSize);
  EXPECT_EQ(leaves_round(whorl, 0.06f), 3);   // three leaf stalks from the centre
  EXPECT_GE(leaves_round(whorl, 0.3f), 7);    // each cut into segments: more than three leaves' worth out there
  const AlphaMask& flower = *wood_anemone_flower_mask();
  ASSERT_EQ(flower.width, kWoodAnemoneMaskSize);
  EXPECT_EQ(leaves_round(flower, 0.35f), kWoodAnemoneTepals);
  EXPECT_TRUE(opaque_at(flower, 0.0f, 0.0f));  // the stamens fill the middle
}

TEST(Understory, NettleStemsCarryDroopingLeafPairsOfBotanicalSize) {
  std::vector<float> tops;  // six to nine pairs up every stem
  const StemmedHerb nettle{"nettle", nettle_pair_mask(), kNettlePairFill, kMinNettleStems, 32, 6, 9, 0.05f, 1.15f};
  // Urtica dioica: leaves 4-15 cm long (5-10 typically; smaller at the top), so a pair 8-32 cm across.
  expect_spans(stemmed_herb_spans(nettle, tops), 0.075f, 0.3f, 0.13f, 0.21f);
  for (float top : tops) EXPECT_GT(top, 0.45f);  // knee-high stands
  const Asset first = make_asset(factory("nettle"), kDefaultAssetSeed, 0);
  for (const MeshPart& p : first.lods()[0].parts) EXPECT_EQ(p.material, Material::Fern);  // dies back in winter
}

TEST(Understory, NettlePairsAreTwoOppositeToothedLeaves) {
  const AlphaMask& m = *nettle_pair_mask();
  ASSERT_EQ(m.width, kNettleMaskSize);
  const auto opaque = [&](float deg, float r) { return opaque_at(m, deg, r); };
  EXPECT_EQ(leaves_round(m, 0.2f), 2);  // one leaf each way
  for (float deg : {90.0f, 270.0f}) {
    EXPECT_TRUE(opaque(deg, 0.2f)) << deg;   // the blade
    EXPECT_TRUE(opaque(deg, 0.36f)) << deg;  // the drawn-out tip
    EXPECT_FALSE(opaque(deg + 90.0f, 0.2f)) << deg;  // nothing across the stem
  }
  // The right leaf's upper edge, column by column, rises and falls with its teeth (a smooth leaf's edge turns once).
  int last = 0, turns = 0, step = 0;
  for (int x = int(0.56f * float(m.width)); x < int(0.94f * float(m.width)); ++x) {
    int top = m.height / 2;
    for (int y = 0; y < m.height / 2; ++y)
      if (m.alpha[size_t(y * m.width + x)] != 0) {
        top = y;
        break;
      }
    if (last != 0 && top != last) {
      const int dir = top > last ? 1 : -1;
      turns += step < 0 && dir > 0;
      step = dir;
    }
    last = top;
  }
  EXPECT_GE(turns, 5);  // one per tooth: the mask has eight a side
}

TEST(Understory, GroundCoverIsSmallCheapAndLabelledGround) {
  for (const Factory& f : factories()) {
    if (f.kind != AssetKind::GroundCover) continue;
    for (uint32_t v = 0; v < f.variants; ++v) {
      const Asset a = make_asset(f, kDefaultAssetSeed, v);
      EXPECT_EQ(a.role, Role::Ground);
      EXPECT_LE(a.lods()[0].triangle_count(), 500u) << a.name;
      const Vec3f size = a.lods()[0].bounds().size();
      EXPECT_LE(size.maxCoeff(), 0.55f) << a.name;
    }
  }
}

}  // namespace
}  // namespace silva::assets
