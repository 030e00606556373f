#include "assets/lod.hpp"

#include <gtest/gtest.h>

#include "assets/alpha_masks.hpp"
#include "assets/mesh_builder.hpp"
#include "assets/strips.hpp"
#include "assets/understory_masks.hpp"
#include "tests/common/mesh_checks.hpp"

namespace silva::assets {
namespace {

/// A mesh with a solid icosphere part and `cards` unit cards in a row.
Mesh sphere_and_cards(int cards) {
  MeshBuilder b;
  b.begin_part(Role::TreeCanopy, Material::Leaves, beech_leaves_mask(), true);
  for (int i = 0; i < cards; ++i) add_card(b, Vec3f(float(3 * i), 0, 0), Vec3f(0.5f, 0, 0), Vec3f(0, 0, 0.5f));
  Mesh m = b.finish();
  Mesh sphere = unit_icosphere(3);
  MeshPart part;
  part.index_count = uint32_t(sphere.indices.size());
  part.role = Role::Obstacle;
  part.material = Material::Rock;
  sphere.parts = {part};
  m.append(sphere);
  return m;
}

TEST(Lod, ThinningKeepsEvenlySpreadCardsEnlargedToKeepArea) {
  const Mesh full = sphere_and_cards(10);
  const Mesh half = reduce_mesh(full, 0.5f);
  test::expect_valid_mesh(half, "half");
  ASSERT_EQ(half.parts.size(), 2u);
  EXPECT_EQ(half.parts[0].index_count, 5u * 6);
  EXPECT_EQ(half.parts[0].mask, full.parts[0].mask);
  // Each kept card is scaled by sqrt(2) about its centre: width 1 -> sqrt(2).
  const float width = (half.positions[1] - half.positions[0]).norm();
  EXPECT_NEAR(width, std::sqrt(2.0f), 1e-5f);
  // Evenly spread: kept card centres are 6 m apart (every second card).
  const float step = (half.positions[4] - half.positions[0]).x();
  EXPECT_NEAR(step, 6.0f, 1e-5f);
}

TEST(Lod, SolidPartsAreSimplifiedAndNeverVanish) {
  const Mesh full = sphere_and_cards(4);
  const uint32_t sphere_tris = full.parts[1].index_count / 3;  // 1280
  const Mesh quarter = reduce_mesh(full, 0.25f);
  const uint32_t reduced = quarter.parts[1].index_count / 3;
  EXPECT_LT(reduced, sphere_tris / 3);
  EXPECT_GT(reduced, sphere_tris / 8);
  const Mesh tiny = reduce_mesh(full, 1e-6f);
  EXPECT_GE(tiny.parts[1].index_count, 3u);
  EXPECT_EQ(tiny.parts[0].index_count, 6u);  // at least one card
  // Simplified vertices stay on (near) the sphere.
  for (uint32_t i = quarter.parts[1].first_index; i < quarter.parts[1].first_index + quarter.parts[1].index_count; ++i)
    EXPECT_NEAR(quarter.positions[quarter.indices[i]].norm(), 1.0f, 1e-4f);
}

TEST(Lod, ChainIsStrictlyDecreasingAndStopsWhenNothingToRemove) {
  const std::vector<Mesh> lods = build_lods(sphere_and_cards(8));
  ASSERT_EQ(lods.size(), 4u);
  for (size_t k = 1; k < lods.size(); ++k) EXPECT_LT(lods[k].triangle_count(), lods[k - 1].triangle_count());
  MeshBuilder b;
  b.begin_part(Role::GroundVegetation, Material::Grass, grass_tuft_mask(), true);
  add_card(b, Vec3f::Zero(), Vec3f::UnitX(), Vec3f::UnitZ());
  EXPECT_EQ(build_lods(b.finish()).size(), 1u);  // one card cannot be reduced
}

TEST(Lod, BentStripsAreThinnedWholeAndScaledAboutTheirBase) {
  MeshBuilder b;
  b.begin_part(Role::GroundVegetation, Material::Fern, pinnate_frond_mask(), true);
  for (int s = 0; s < 4; ++s) {  // four 3-quad strips rising from x = 2 s
    const Vec3f base(float(2 * s), 0, 0);
    const StripNode spine[] = {{base, 0.1f}, {base + Vec3f(0, 0, 1), 0.1f}, {base + Vec3f(0, 0.5f, 2), 0.1f},
                               {base + Vec3f(0, 1.5f, 2.5f), 0.1f}};
    add_strip(b, spine, Vec3f::UnitX());
  }
  const Mesh full = b.finish();
  const Mesh half = reduce_mesh(full, 0.5f);
  ASSERT_EQ(half.parts[0].index_count, 2u * 3 * 6);  // two whole strips
  // The kept strips' bases stay on the ground; their tips reach sqrt(2) further.
  float lowest = 1e9f, highest = 0;
  for (const Vec3f& p : half.positions) lowest = std::min(lowest, p.z()), highest = std::max(highest, p.z());
  EXPECT_NEAR(lowest, 0.0f, 1e-6f);
  EXPECT_NEAR(highest, 2.5f * std::sqrt(2.0f), 1e-4f);
}

}  // namespace
}  // namespace silva::assets
