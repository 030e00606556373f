// Known answers of the understory and forest-floor generators.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "assets/factory.hpp"
#include "assets/rock_shape.hpp"
#include "assets/understory_masks.hpp"

namespace silva::assets {
namespace {

const Factory& factory(const char* prefix) {
  for (const Factory& f : factories())
    if (std::string(f.prefix) == prefix) return f;
  throw std::runtime_error(prefix);
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
