// Known answers of the grass sward: botanical blade widths, thousands of blades per square metre.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <vector>

#include "assets/factory.hpp"
#include "assets/generators.hpp"
#include "assets/understory_masks.hpp"

namespace silva::assets {
namespace {

/// Widths (texels) of the runs of opaque texels along row y of `m`.
std::vector<int> opaque_runs(const AlphaMask& m, int y) {
  std::vector<int> runs;
  int run = 0;
  for (int x = 0; x <= m.width; ++x) {
    if (x < m.width && m.alpha[size_t(y * m.width + x)] != 0) {
      ++run;
    } else if (run > 0) {
      runs.push_back(run);
      run = 0;
    }
  }
  return runs;
}

TEST(GrassSward, BladesAreSeparateAndOfWoodlandGrassWidth) {
  const AlphaMask& m = *grass_sward_mask();
  ASSERT_EQ(m.width, kGrassSwardMaskWidth);
  ASSERT_EQ(m.height, kGrassSwardMaskHeight);
  // 1.5 cm above the ground in a 10 cm card (the lowest centimetre lies in the litter): single blades.
  const std::vector<int> runs = opaque_runs(m, m.height - m.height * 25 / 100);
  ASSERT_GE(runs.size(), 20u);  // blades stand apart (20 or more runs of 52 blades), not in one band
  std::vector<float> widths_mm;
  for (int r : runs) widths_mm.push_back(1000.0f * kGrassSwardCardWidth * float(r) / float(m.width));
  std::sort(widths_mm.begin(), widths_mm.end());
  // Wavy hair-grass, wood meadow-grass, bents: leaves 1-4 mm wide.
  EXPECT_GE(widths_mm[widths_mm.size() / 2], 1.0f);
  EXPECT_LE(widths_mm[widths_mm.size() / 2], 4.0f);
  std::set<uint8_t> shades(m.alpha.begin(), m.alpha.end());
  EXPECT_GE(shades.size(), 12u);  // each blade its own brightness
}

TEST(GrassSward, PatchesCarryThousandsOfLowBladesPerSquareMetre) {
  const Factory* f = find_factory("grass_sward");
  ASSERT_NE(f, nullptr);
  for (uint32_t v = 0; v < f->variants; ++v) {
    const Asset a = make_asset(*f, kDefaultAssetSeed, v);
    ASSERT_EQ(a.lods().size(), 1u) << a.name;  // cards only: labels stay LOD-independent
    const Mesh& m = a.lods()[0];
    ASSERT_EQ(m.parts.size(), 1u);
    EXPECT_EQ(m.parts[0].mask, grass_sward_mask());
    EXPECT_EQ(m.parts[0].material, Material::Grass);
    const size_t cards = m.triangle_count() / 4;  // two quads a card
    ASSERT_EQ(cards * 4, m.triangle_count());
    float radius = 0.0f, top = 0.0f;
    for (const Vec3f& p : m.positions) {
      if (p.z() < 0.0f) radius = std::max(radius, p.head<2>().norm());  // card base corners
      top = std::max(top, p.z());
    }
    const float area = std::numbers::pi_v<float> * radius * radius;
    const float blades_per_m2 = float(cards * size_t(kGrassSwardBlades)) / area;
    EXPECT_GE(blades_per_m2, 3000.0f) << a.name;
    EXPECT_LE(blades_per_m2, 12000.0f) << a.name;
    EXPECT_GE(2.0f * radius, 0.3f) << a.name;  // a patch, not a tuft
    EXPECT_GE(top, 0.03f) << a.name;
    EXPECT_LE(top, 0.2f) << a.name;
  }
}

}  // namespace
}  // namespace silva::assets
