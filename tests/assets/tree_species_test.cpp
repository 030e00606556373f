// Grown trees per species: foliage off the trunk, no thin tubes, age classes, bark uv.
#include "assets/species.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace silva::assets {
namespace {

const Species* const kAll[] = {&norway_spruce(), &scots_pine(), &european_larch(),
                               &european_beech(), &silver_birch(), &common_oak()};

/// A mature skeleton of a species (its table's branching at the middle of the mature range).
Skeleton mature(const Species& sp, Rng& rng) {
  SkeletonParams p = sp.skeleton;
  p.height = 0.5f * (sp.mature_min + sp.mature_max) * sp.trunk_share;
  p.base_radius = p.height * sp.slenderness;
  return grow_skeleton(p, rng);
}

/// Distance from p to the trunk's centre line minus the trunk radius there (< 0: inside).
float outside_trunk(const Skeleton& s, const Vec3f& p) {
  float best = 1e9f;
  const auto& n = s.branches.front().nodes;
  for (size_t i = 1; i < n.size(); ++i) {
    const Vec3f ab = n[i].p - n[i - 1].p;
    const float t = std::clamp((p - n[i - 1].p).dot(ab) / ab.squaredNorm(), 0.0f, 1.0f);
    best = std::min(best, (p - (n[i - 1].p + t * ab)).norm() - (n[i - 1].r + t * (n[i].r - n[i - 1].r)));
  }
  return best;
}

TEST(TreeSpecies, NoFoliageCardCentreInsideTheTrunk) {
  for (const Species* sp : kAll) {
    SCOPED_TRACE(sp->name);
    Rng rng(11, 2, Purpose::AssetShape);
    const Skeleton s = mature(*sp, rng);
    MeshBuilder b;
    mesh_tree(b, s, sp->look, rng);
    const Mesh m = b.finish();
    size_t cards = 0;
    for (const MeshPart& part : m.parts) {
      if (!part.mask) continue;
      EXPECT_EQ(part.role, Role::TreeCanopy);
      EXPECT_TRUE(part.double_sided);
      for (uint32_t q = part.first_index; q < part.first_index + part.index_count; q += 6, ++cards) {
        Vec3f c = Vec3f::Zero();
        for (int k = 0; k < 6; ++k) c += m.positions[m.indices[q + uint32_t(k)]] / 6.0f;
        EXPECT_GT(outside_trunk(s, c), 0.0f);
      }
    }
    EXPECT_GT(cards, 300u);
    EXPECT_LE(cards, size_t(sp->look.cards.max_cards) * 11 / 10);
  }
}

TEST(TreeSpecies, TubesAreNeverThinnerThanTheMinimumRadius) {
  // A tube ring of radius r with s <= 12 sides has edges 2 r sin(pi / s) >= 2 r sin(pi / 12): no bark
  // edge may be shorter than that of a kMinTubeRadius ring, while a 5 mm twig's would be.
  const float shortest = 2.0f * kMinTubeRadius * std::sin(std::numbers::pi_v<float> / 12.0f) * 0.99f;
  for (const Species* sp : kAll) {
    SCOPED_TRACE(sp->name);
    Rng rng(12, 2, Purpose::AssetShape);
    const Skeleton s = mature(*sp, rng);
    MeshBuilder b;
    TreeLook bare = sp->look;
    bare.foliage = false;
    mesh_tree(b, s, bare, rng);
    const Mesh m = b.finish();
    ASSERT_EQ(m.parts.size(), 1u);
    EXPECT_EQ(m.parts[0].material, sp->look.bark);
    for (size_t t = 0; t < m.indices.size(); t += 3)
      for (int e = 0; e < 3; ++e)
        ASSERT_GE((m.positions[m.indices[t + size_t(e)]] - m.positions[m.indices[t + size_t(e + 1) % 3]]).norm(), shortest);
    EXPECT_GT(std::count_if(s.branches.begin(), s.branches.end(), [](const Branch& br) { return br.nodes.front().r < kMinTubeRadius; }), 0);
    for (const Vec2f& uv : m.uvs) EXPECT_LE(uv.y(), 1.0f + 1e-5f);  // height fraction of the tree
  }
}

TEST(TreeSpecies, VariantsSpanAgeClassesWithinTheSpeciesSize) {
  for (const Species* sp : kAll) {
    SCOPED_TRACE(sp->name);
    float lowest = 1e9f, highest = 0;
    for (uint64_t v = 0; v < 24; ++v) {
      Rng rng(13, v, Purpose::AssetShape);
      const GeneratedAsset a = grow_tree(*sp, rng);
      const AABB box = a.mesh.bounds();
      lowest = std::min(lowest, box.max.z());
      highest = std::max(highest, box.max.z());
      EXPECT_GE(box.max.z(), 0.9f);
      EXPECT_LE(box.max.z(), 1.2f * sp->mature_max);
      EXPECT_EQ(a.role, Role::TreeTrunk);
      EXPECT_EQ(a.proxy.shape, CollisionProxy::Shape::Cylinder);
      EXPECT_GT(a.proxy.radius, 0.01f);
      EXPECT_LE(a.proxy.height, box.max.z());
    }
    EXPECT_LT(lowest, 3.5f);                      // a sapling
    EXPECT_GT(highest, 0.8f * sp->mature_min);    // a mature tree
  }
}

}  // namespace
}  // namespace silva::assets
