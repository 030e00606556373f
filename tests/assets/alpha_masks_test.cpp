#include "assets/alpha_masks.hpp"
#include "assets/understory_masks.hpp"

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
  for (const auto& mask : {bare_twig_mask()}) {
    ASSERT_EQ(mask->width, kMaskSize);
    ASSERT_EQ(mask->height, kMaskSize);
    ASSERT_EQ(mask->alpha.size(), size_t(kMaskSize * kMaskSize));
    for (uint8_t a : mask->alpha) ASSERT_TRUE(a == 0 || a == 255);
    EXPECT_GT(coverage(*mask), 0.1);
    EXPECT_LT(coverage(*mask), 0.75);
    EXPECT_EQ(mask->cutoff, 0.5f);
  }
}

TEST(AlphaMasks, UnderstoryMasksAreBinaryAndPartlyOpaque) {
  for (const auto& mask : {pinnate_frond_mask(), grass_tuft_mask(), grass_seed_mask(), bilberry_leaves_mask(),
                           hazel_leaves_mask(), bramble_leaf_mask(), litter_leaves_mask()}) {
    ASSERT_EQ(mask->alpha.size(), size_t(mask->width) * size_t(mask->height));
    for (uint8_t a : mask->alpha) ASSERT_TRUE(a == 0 || a == 255);
    EXPECT_GT(coverage(*mask), 0.08);
    EXPECT_LT(coverage(*mask), 0.75);
  }
}

TEST(AlphaMasks, SharedAcrossCalls) { EXPECT_EQ(bare_twig_mask(), bare_twig_mask()); }

TEST(AlphaMasks, GrassGrowsFromTheBottomEdgeAndTapers) {
  for (const auto& mask : {grass_tuft_mask(), grass_seed_mask()}) {
    EXPECT_GT(row_coverage(*mask, mask->height - 1), 3 * row_coverage(*mask, 4));
    EXPECT_FALSE(mask->opaque(0.02f, 0.02f));  // top-left corner is empty
  }
}

TEST(AlphaMasks, FrondHasAStemAlongV) {
  const auto mask = pinnate_frond_mask();
  for (float v : {0.3f, 0.6f, 0.95f}) EXPECT_TRUE(mask->opaque(0.5f, v)) << v;
  EXPECT_FALSE(mask->opaque(0.02f, 0.98f));
}

}  // namespace
}  // namespace silva::assets
