// Coverage blend of minified alpha masks: known answers on a checkerboard of leaf and background, what it
// leaves alone (magnified masks, solid surfaces in front), and independence of the order rows are blended in.
#include "render/foliage_aa.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <numeric>
#include <random>

namespace silva::render {
namespace {

const Vec3f kLeaf(1, 0, 0);        ///< Radiance of the leaf pixels.
const Vec3f kBackground(0, 0, 1);  ///< Radiance of the pixels behind.

/// A size x size view: leaf pixels (depth 10, `texels` mask texels across) where (u + v) is even, background
/// at depth 30 elsewhere; `frame` gets their radiance.
GBuffer checkerboard(int size, float texels, LinearFrame& frame) {
  GBuffer g;
  g.resize(size, size);
  frame.resize(size, size);
  for (int v = 0; v < size; ++v)
    for (int u = 0; u < size; ++u) {
      const size_t i = size_t(v) * size_t(size) + size_t(u);
      const bool leaf = (u + v) % 2 == 0;
      g.depth[i] = leaf ? 10.0f : 30.0f;
      g.mask_texels[i] = leaf ? texels : 0.0f;
      frame.rgb[i] = leaf ? kLeaf : kBackground;
    }
  return g;
}

/// Blends every row of `frame` in `order` (default top to bottom) with one MaskBlendRows; returns the result.
std::vector<Vec3f> blended(const GBuffer& g, float exposure, const LinearFrame& frame, std::vector<int> order = {}) {
  if (order.empty()) {
    order.resize(size_t(g.height));
    std::iota(order.begin(), order.end(), 0);
  }
  std::vector<Vec3f> out(frame.rgb.size());
  MaskBlendRows rows(g, exposure, frame);
  for (const int v : order) rows.blend(v, &out[size_t(v) * size_t(g.width)]);
  return out;
}

/// Replaces `frame` by its blend.
void blend_frame(const GBuffer& g, float exposure, LinearFrame& frame) { frame.rgb = blended(g, exposure, frame); }

TEST(FoliageAa, WeightRampsFromOneToThreeTexelsAcross) {
  EXPECT_EQ(minified_weight(0.0f), 0.0f);
  EXPECT_EQ(minified_weight(1.0f), 0.0f);
  EXPECT_FLOAT_EQ(minified_weight(2.0f), 0.5f);
  EXPECT_EQ(minified_weight(3.0f), 1.0f);
  EXPECT_EQ(minified_weight(40.0f), 1.0f);
}

TEST(FoliageAa, ACheckerboardOfLeafAndBackgroundBlendsToKnownMixes) {
  LinearFrame frame;
  const GBuffer g = checkerboard(5, 8.0f, frame);
  ASSERT_TRUE(has_minified_masks(g));
  blend_frame(g, 0.0f, frame);
  // A leaf pixel: itself (4), its four sides behind it (2 each) and four leaf corners (1 each): 8/16 leaf.
  const Vec3f leaf_mix = frame.rgb[2 * 5 + 2];
  EXPECT_FLOAT_EQ(leaf_mix.x(), 0.5f);
  EXPECT_FLOAT_EQ(leaf_mix.z(), 0.5f);
  // A background pixel: itself (4) and the four leaf pixels in front of it at its sides (2 each); its
  // background corners lie on its own layer but carry no mask: 8/12 leaf.
  const Vec3f background_mix = frame.rgb[2 * 5 + 1];
  EXPECT_FLOAT_EQ(background_mix.x(), 2.0f / 3.0f);
  EXPECT_FLOAT_EQ(background_mix.z(), 1.0f / 3.0f);
  // A corner leaf pixel has three neighbours: one leaf corner (1) and two background sides (2 each).
  EXPECT_FLOAT_EQ(frame.rgb[0].x(), 5.0f / 9.0f);
}

TEST(FoliageAa, KnownMixesHoldAlongAWideRow) {
  // Wide enough for the SIMD lanes of every target: every inside pixel has the 5 x 5 board's mixes.
  LinearFrame frame;
  const GBuffer g = checkerboard(41, 8.0f, frame);
  blend_frame(g, 0.0f, frame);
  for (int v = 1; v < 40; ++v)
    for (int u = 1; u < 40; ++u) {
      const Vec3f& c = frame.rgb[size_t(v) * 41 + size_t(u)];
      EXPECT_FLOAT_EQ(c.x(), (u + v) % 2 == 0 ? 0.5f : 2.0f / 3.0f) << u << ", " << v;
      EXPECT_FLOAT_EQ(c.x() + c.z(), 1.0f) << u << ", " << v;
    }
}

TEST(FoliageAa, SkyGapsTakeTheLeavesColourButGiveTheLeavesNone) {
  LinearFrame frame;
  GBuffer g = checkerboard(5, 8.0f, frame);
  for (size_t i = 0; i < g.size(); ++i)
    if (g.mask_texels[i] == 0.0f) g.depth[i] = 0.0f;  // the background is sky
  blend_frame(g, 0.0f, frame);
  EXPECT_EQ(frame.rgb[2 * 5 + 2], kLeaf);                        // itself and its four leaf corners
  EXPECT_FLOAT_EQ(frame.rgb[2 * 5 + 1].x(), 2.0f / 3.0f);        // a gap: itself (4), four leaves (2 each)
}

TEST(FoliageAa, BrightPixelsWeighByTheirTone) {
  // At exposure 1 the background's luminance is 0.0722 x 9 = 0.65: weight 1 / 1.65 against the leaves'
  // 1 / (1 + 0.2126 x 0) = 1. A leaf pixel then holds leaf 8 / (8 + 8 / 1.65) of the mix.
  LinearFrame frame;
  GBuffer g = checkerboard(5, 8.0f, frame);
  for (Vec3f& c : frame.rgb) c = c.z() > 0.0f ? Vec3f(0, 0, 9) : Vec3f(1, 0, 0);
  for (Vec3f& c : frame.rgb) c.x() = c.x() > 0.0f ? 1e-30f : 0.0f;  // leaves with no light: tone weight 1
  blend_frame(g, 1.0f, frame);
  const float sky = 1.0f / (1.0f + 0.0722f * 9.0f);
  EXPECT_NEAR(frame.rgb[2 * 5 + 2].z(), 9.0f * 8.0f * sky / (8.0f + 8.0f * sky), 1e-5f);
}

TEST(FoliageAa, MagnifiedMasksAndFramesWithoutMasksAreLeftAlone) {
  LinearFrame frame;
  const GBuffer g = checkerboard(5, 0.8f, frame);
  EXPECT_FALSE(has_minified_masks(g));
  const std::vector<Vec3f> before = frame.rgb;
  blend_frame(g, 0.0f, frame);
  EXPECT_EQ(frame.rgb, before);
}

TEST(FoliageAa, ASolidSurfaceInFrontKeepsItsEdgeAndItsColour) {
  // Column 0 is a solid trunk at depth 5 in front of the minified leaves: the trunk takes none of the
  // leaves behind it and the leaves take none of the trunk.
  LinearFrame frame;
  GBuffer g = checkerboard(5, 8.0f, frame);
  for (int v = 0; v < 5; ++v) {
    const size_t i = size_t(v) * 5;
    g.depth[i] = 5.0f;
    g.mask_texels[i] = 0.0f;
    frame.rgb[i] = Vec3f(0, 1, 0);
  }
  blend_frame(g, 0.0f, frame);
  for (int v = 0; v < 5; ++v) {
    EXPECT_EQ(frame.rgb[size_t(v) * 5], Vec3f(0, 1, 0)) << v;
    EXPECT_EQ(frame.rgb[size_t(v) * 5 + 1].y(), 0.0f) << v;
  }
}

TEST(FoliageAa, RowsComeOutTheSameInAnyOrder) {
  // shade_rgb blends most rows of a band right after shading them and the band's first and last later, on
  // whichever thread: a row's blend must not depend on the rows blended before it.
  std::mt19937 gen(3);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  LinearFrame frame;
  GBuffer g;
  g.resize(97, 61);
  frame.resize(97, 61);
  for (size_t i = 0; i < g.size(); ++i) {
    g.depth[i] = unit(gen) < 0.1f ? 0.0f : 1.0f + 50.0f * unit(gen);
    g.mask_texels[i] = 4.0f * unit(gen);
    frame.rgb[i] = Vec3f(unit(gen), unit(gen), unit(gen));
  }
  const std::vector<Vec3f> top_down = blended(g, 1.0f, frame);
  std::vector<int> order(size_t(g.height));
  std::iota(order.begin(), order.end(), 0);
  std::reverse(order.begin(), order.end());
  EXPECT_EQ(blended(g, 1.0f, frame, order), top_down);
  std::shuffle(order.begin(), order.end(), gen);
  EXPECT_EQ(blended(g, 1.0f, frame, order), top_down);
  EXPECT_NE(top_down, frame.rgb);  // the frame is minified enough to change
}

}  // namespace
}  // namespace silva::render
