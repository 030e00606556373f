#include "assets/alpha_masks.hpp"

#include <gtest/gtest.h>

namespace silva::assets {
namespace {

double coverage(const AlphaMask& m) {
  size_t n = 0;
  for (uint8_t a : m.alpha) n += a >= 128;
  return double(n) / double(m.alpha.size());
}

/// Opaque fraction of one row.
double row_coverage(const AlphaMask& m, int y) {
  size_t n = 0;
  for (int x = 0; x < m.width; ++x) n += m.alpha[size_t(y) * size_t(m.width) + size_t(x)] >= 128;
  return double(n) / m.width;
}

TEST(AlphaMasks, AllAreBinarySquareAndPartlyOpaque) {
  for (const auto& mask : {needle_spray_mask(), grass_blades_mask(), fern_frond_mask(), shrub_leaves_mask(),
                           pine_tuft_mask(), larch_tuft_mask(), beech_leaves_mask(), birch_leaves_mask(),
                           oak_leaves_mask(), bare_twig_mask()}) {
    ASSERT_EQ(mask->width, kMaskSize);
    ASSERT_EQ(mask->height, kMaskSize);
    ASSERT_EQ(mask->alpha.size(), size_t(kMaskSize * kMaskSize));
    for (uint8_t a : mask->alpha) ASSERT_TRUE(a == 0 || a == 255);
    EXPECT_GT(coverage(*mask), 0.1);
    EXPECT_LT(coverage(*mask), 0.75);
    EXPECT_EQ(mask->cutoff, 0.5f);
  }
}

TEST(AlphaMasks, SharedAcrossCalls) { EXPECT_EQ(beech_leaves_mask(), beech_leaves_mask()); }

TEST(AlphaMasks, GrassGrowsFromTheBottomEdgeAndTapers) {
  const AlphaMask& g = *grass_blades_mask();
  EXPECT_GT(row_coverage(g, kMaskSize - 1), 3 * row_coverage(g, 4));
  EXPECT_TRUE(g.opaque(0.47f, 0.99f));  // a blade base
  EXPECT_FALSE(g.opaque(0.02f, 0.02f));  // top-left corner is empty
}

TEST(AlphaMasks, FrondsAndSpraysHaveAStemAlongV) {
  for (const auto& mask : {fern_frond_mask(), needle_spray_mask(), larch_tuft_mask(), beech_leaves_mask(),
                           birch_leaves_mask(), oak_leaves_mask()}) {
    for (float v : {0.3f, 0.6f, 0.95f}) EXPECT_TRUE(mask->opaque(0.5f, v)) << v;
    EXPECT_FALSE(mask->opaque(0.02f, 0.98f));
  }
}

}  // namespace
}  // namespace silva::assets
