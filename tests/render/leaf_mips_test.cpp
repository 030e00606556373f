// Leaf brightness mips (render/leaf_mips.hpp): known answers on a small mask, the level a footprint
// selects, and opacity kept across levels on a random mask.
#include <gtest/gtest.h>

#include <random>

#include "render/leaf_mips.hpp"
#include "render/materials.hpp"

namespace silva::render {
namespace {

/// A width x height mask with the given row-major alphas.
AlphaMask mask_of(int width, int height, std::vector<uint8_t> alpha) {
  AlphaMask m;
  m.width = width;
  m.height = height;
  m.alpha = std::move(alpha);
  return m;
}

TEST(LeafMips, CoarseTexelsHoldTheMeanBrightnessOfTheirOpaqueTexels) {
  // Three 2x2 blocks: brightness 0.75 and 1.25 around two holes (mean 1.0: alpha 191); one leaf of
  // 1.25 (254) and alpha 255 (no own value: 1.0) (mean 1.125: alpha 223); only holes (0).
  const AlphaMask m = mask_of(6, 2, {128, 254, 254, 0, 0, 0,  //
                                     0, 100, 255, 0, 127, 0});
  const LeafMips mips = LeafMips::of(m);
  ASSERT_EQ(mips.coarse_levels(), 1);  // 3 x 1 cannot halve again
  EXPECT_EQ(leaf_brightness(191), 1.0f);
  EXPECT_EQ(mips.alpha(m, 0.1f, 0.5f, 2.0f), 191);
  EXPECT_EQ(mips.alpha(m, 0.5f, 0.5f, 3.9f), 223);
  EXPECT_EQ(mips.alpha(m, 0.9f, 0.5f, 100.0f), 0);
}

TEST(LeafMips, FootprintsBelowTwoTexelsReadTheMaskItself) {
  const AlphaMask m = mask_of(4, 4, {130, 250, 0, 140, 0, 0, 0, 0, 200, 200, 200, 200, 0, 0, 0, 0});
  const LeafMips mips = LeafMips::of(m);
  ASSERT_EQ(mips.coarse_levels(), 2);
  EXPECT_EQ(mips.alpha(m, 0.1f, 0.1f, 0.0f), 130);
  EXPECT_EQ(mips.alpha(m, 0.3f, 0.1f, 1.99f), 250);
  EXPECT_EQ(mips.alpha(m, 0.3f, 0.1f, 2.0f), 190);  // level 1: (0.75 + 1.2262) / 2 of 130 and 250
  EXPECT_EQ(mips.alpha(m, 0.3f, 0.1f, 4.0f), mips.alpha(m, 0.3f, 0.1f, 1e6f));  // level 2 is the coarsest
}

TEST(LeafMips, EveryLevelKeepsAUniformLeafAndTheOpacityOfLevelZero) {
  for (int a = 128; a <= 254; ++a) {
    const AlphaMask uniform = mask_of(8, 8, std::vector<uint8_t>(64, uint8_t(a)));
    const LeafMips mips = LeafMips::of(uniform);
    for (const float across : {2.0f, 4.0f, 8.0f}) EXPECT_EQ(mips.alpha(uniform, 0.4f, 0.7f, across), a) << across;
  }
  std::mt19937 gen(5);
  std::vector<uint8_t> alpha(256 * 128);
  for (uint8_t& t : alpha) t = gen() % 3 == 0 ? uint8_t(128 + gen() % 128) : uint8_t(gen() % 128);
  const AlphaMask m = mask_of(256, 128, alpha);
  const LeafMips mips = LeafMips::of(m);
  EXPECT_EQ(mips.coarse_levels(), 7);
  std::uniform_real_distribution<float> coord(-3.0f, 3.0f);
  int opaque = 0;
  for (int k = 0; k < 20000; ++k) {
    const float u = coord(gen), v = coord(gen);
    if (!m.opaque(u, v)) continue;
    ++opaque;
    for (int level = 1; level <= 8; ++level) ASSERT_GE(mips.alpha(m, u, v, float(1 << level)), 128) << u << "," << v;
  }
  EXPECT_GT(opaque, 5000);
}

}  // namespace
}  // namespace silva::render
