// Opacity bit tables of alpha masks (core/alpha_bits.hpp): known answers against the byte masks.
#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "core/alpha_bits.hpp"
#include "core/error.hpp"

namespace silva {
namespace {

/// A width x height mask of random alpha bytes.
std::shared_ptr<AlphaMask> random_mask(int width, int height, float cutoff, unsigned seed) {
  std::mt19937 gen(seed);
  auto m = std::make_shared<AlphaMask>();
  m->width = width;
  m->height = height;
  m->cutoff = cutoff;
  for (int i = 0; i < width * height; ++i) m->alpha.push_back(uint8_t(gen() % 256));
  return m;
}

TEST(AlphaBits, EveryTexelMatchesTheByteMask) {
  // Sizes below, at and across the 32-texel word boundary, and cutoffs on both sides of 0.5.
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{1, 1}, {5, 1}, {31, 1}, {32, 2}, {33, 3}, {64, 64}, {37, 5}})
    for (const float cutoff : {0.1f, 0.5f, 0.9f}) {
      const auto mask = random_mask(w, h, cutoff, unsigned(w * 100 + h));
      const AlphaBits bits = AlphaBits::of(*mask);
      ASSERT_EQ(bits.words.size(), size_t((w * h + 31) / 32));
      int opaque = 0;
      for (int i = 0; i < w * h; ++i) {
        ASSERT_EQ(bits.opaque_texel(i), mask->opaque_texel(i)) << w << "x" << h << " texel " << i;
        opaque += mask->opaque_texel(i) ? 1 : 0;
      }
      if (w * h >= 64) {
        EXPECT_GT(opaque, 0);
        EXPECT_LT(opaque, w * h);
      }
    }
}

TEST(AlphaBits, LookupsWrapLikeTheByteMask) {
  const auto mask = random_mask(37, 5, 0.5f, 11);
  const AlphaBits bits = AlphaBits::of(*mask);
  std::mt19937 gen(3);
  std::uniform_real_distribution<float> coord(-3.0f, 3.0f);
  for (int k = 0; k < 20000; ++k) {
    const float u = coord(gen), v = coord(gen);
    ASSERT_EQ(bits.opaque(u, v), mask->opaque(u, v)) << u << ", " << v;
  }
  // Texel 36 of row 0 is the last of the first row: u just below 1 reads it, u = 1 wraps to texel 0.
  EXPECT_EQ(bits.opaque(0.9999f, 0.1f), mask->opaque_texel(36));
  EXPECT_EQ(bits.opaque(1.0f, 0.1f), mask->opaque_texel(0));
}

TEST(AlphaBits, AMaskWhoseSizeDisagreesWithItsBytesIsAnInputError) {
  auto mask = random_mask(4, 4, 0.5f, 1);
  mask->alpha.pop_back();
  try {
    (void)AlphaBits::of(*mask);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("4x4"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("15 alpha values"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace silva
