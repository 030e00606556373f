// Known answers of the branching skeleton generator on a fixed parameter set.
#include "assets/tree_skeleton.hpp"

#include <gtest/gtest.h>

#include "assets/dead_wood.hpp"

namespace silva::assets {
namespace {

/// Trunk with 6 first-order branches in whorls of 3, each with 4 twigs; no random length loss.
SkeletonParams fixed_params() {
  SkeletonParams p;
  p.height = 10.0f;
  p.base_radius = 0.2f;
  p.shape = CrownShape::Conical;
  p.levels = {{.children = 6, .whorl = 3, .start = 0.3f, .rotate = 60, .curve_var = 2, .tip_radius = 0.05f, .segments = 6},
              {.children = 4, .start = 0.2f, .length = 0.3f, .length_var = 0.1f, .down = 80, .down_tip = 50,
               .down_var = 5, .rotate = 180, .curve = 20, .curve_var = 5, .tropism = 0.05f, .tip_radius = 0.1f,
               .segments = 4},
              {.length = 0.4f, .down = 45, .down_var = 10, .tropism = 0.2f, .apical = 0.5f, .tip_radius = 0.3f,
               .segments = 2}};
  return p;
}

Skeleton grow(uint64_t seed) {
  Rng rng(seed, 1, Purpose::AssetShape);
  return grow_skeleton(fixed_params(), rng);
}

TEST(TreeSkeleton, BranchCountPerLevel) {
  const Skeleton s = grow(3);
  EXPECT_EQ(s.count(0), 1);
  EXPECT_EQ(s.count(1), 6);
  EXPECT_EQ(s.count(2), 24);
  EXPECT_EQ(s.branches.size(), 31u);
  EXPECT_EQ(s.branches[0].parent, -1);
  EXPECT_NEAR(s.branches[0].length, 10.0f, 1e-4f);
  EXPECT_NEAR(s.branches[0].nodes.front().r, 0.2f, 1e-6f);
}

TEST(TreeSkeleton, ChildrenStartOnTheirParentNoThickerThanItThere) {
  const Skeleton s = grow(4);
  for (size_t i = 1; i < s.branches.size(); ++i) {
    const Branch& c = s.branches[i];
    ASSERT_GE(c.parent, 0);
    ASSERT_LT(size_t(c.parent), i);  // parents come first
    const Branch& parent = s.branches[size_t(c.parent)];
    EXPECT_EQ(c.level, parent.level + 1);
    const TubeNode at = point_along(parent, c.parent_t);
    EXPECT_LT((c.nodes.front().p - at.p).norm(), 1e-4f) << i;
    EXPECT_LE(c.nodes.front().r, at.r) << i;
    EXPECT_GE(c.parent_t, 0.2f);
  }
}

TEST(TreeSkeleton, RadiusNeverGrowsAlongABranchAndLengthsAddUp) {
  const Skeleton s = grow(5);
  for (const Branch& b : s.branches) {
    float length = 0;
    for (size_t k = 1; k < b.nodes.size(); ++k) {
      EXPECT_LE(b.nodes[k].r, b.nodes[k - 1].r);
      length += (b.nodes[k].p - b.nodes[k - 1].p).norm();
    }
    EXPECT_NEAR(length, b.length, 1e-3f * b.length);
  }
}

TEST(TreeSkeleton, FirstOrderBranchesFollowTheConicalCrown) {
  // Conical: the lowest first-order branch is longer than the highest.
  const Skeleton s = grow(6);
  float low = 0, high = 0, low_t = 2, high_t = -1;
  for (const Branch& b : s.branches)
    if (b.level == 1) {
      if (b.parent_t < low_t) low_t = b.parent_t, low = b.length;
      if (b.parent_t > high_t) high_t = b.parent_t, high = b.length;
    }
  EXPECT_GT(low, 1.5f * high);
}

TEST(TreeSkeleton, SameSeedSameTreeOtherSeedOtherTree) {
  const Skeleton a = grow(7), b = grow(7), c = grow(8);
  ASSERT_EQ(a.branches.size(), b.branches.size());
  for (size_t i = 0; i < a.branches.size(); ++i)
    for (size_t k = 0; k < a.branches[i].nodes.size(); ++k)
      EXPECT_EQ(a.branches[i].nodes[k].p, b.branches[i].nodes[k].p);
  EXPECT_NE(a.branches[1].nodes.back().p, c.branches[1].nodes.back().p);
}

TEST(TreeSkeleton, TruncatingABranchDropsWhatForkedBeyondTheCut) {
  Skeleton s = grow(9);
  truncate_branch(s, 0, 0.5f);
  EXPECT_NEAR(s.branches[0].length, 5.0f, 1e-3f);
  EXPECT_LT(s.count(1), 6);
  for (size_t i = 1; i < s.branches.size(); ++i) {
    const Branch& c = s.branches[i];
    ASSERT_GE(c.parent, 0);
    ASSERT_LT(size_t(c.parent), i);
    EXPECT_EQ(c.level, s.branches[size_t(c.parent)].level + 1);
    EXPECT_LE(c.parent_t, 1.0f);
  }
}

}  // namespace
}  // namespace silva::assets
