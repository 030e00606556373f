#include "assets/lod.hpp"

#include <gtest/gtest.h>

#include "assets/alpha_masks.hpp"
#include "assets/mesh_builder.hpp"
#include "assets/strips.hpp"
#include "assets/understory_masks.hpp"
#include "tests/assets/card_meshes.hpp"
#include "tests/common/mesh_checks.hpp"

namespace silva::assets {
namespace {

/// A mesh with `cards` unit cards in a row (part 0) and a solid icosphere (part 1).
Mesh sphere_and_cards(int cards) { return test::cards_and_sphere(cards, Role::Obstacle, Material::Rock); }

TEST(Lod, CardsAreKeptWholeSoTheirCoverageAndLabelsStay) {
  const Mesh full = sphere_and_cards(10);
  const Mesh reduced = reduce_mesh(full, 0.1f, 0.05f);
  test::expect_valid_mesh(reduced, "reduced");
  ASSERT_EQ(reduced.parts.size(), 2u);
  EXPECT_LT(reduced.parts[1].index_count, full.parts[1].index_count);
  ASSERT_EQ(reduced.parts[0].index_count, full.parts[0].index_count);
  EXPECT_EQ(reduced.parts[0].mask, full.parts[0].mask);
  for (uint32_t i = 0; i < full.parts[0].index_count; ++i)
    EXPECT_EQ(reduced.positions[reduced.indices[i]], full.positions[full.indices[i]]);
}

TEST(Lod, SimplificationStaysWithinItsErrorBound) {
  const Mesh full = sphere_and_cards(1);
  // The extent is 2 (the unit sphere); a bound of 0.001 relative is 2 mm, far below what a 10 % sphere needs.
  const Mesh tight = reduce_mesh(full, 0.1f, 0.001f);
  const Mesh loose = reduce_mesh(full, 0.1f, 0.05f);
  EXPECT_GT(tight.parts[1].index_count, 2 * loose.parts[1].index_count);
  for (uint32_t i = tight.parts[1].first_index; i < tight.parts[1].first_index + tight.parts[1].index_count; ++i)
    EXPECT_NEAR(tight.positions[tight.indices[i]].norm(), 1.0f, 1e-4f);
  EXPECT_NEAR(lod_error_bound(0.25f), 1.0f / 270.0f, 1e-7f);
}

TEST(Lod, SolidPartsAreSimplifiedAndNeverVanish) {
  const Mesh full = sphere_and_cards(4);
  const uint32_t sphere_tris = full.parts[1].index_count / 3;  // 1280
  const Mesh quarter = reduce_mesh(full, 0.25f, 0.05f);
  const uint32_t reduced = quarter.parts[1].index_count / 3;
  EXPECT_LT(reduced, sphere_tris / 3);
  EXPECT_GT(reduced, sphere_tris / 8);
  const Mesh tiny = reduce_mesh(full, 1e-6f, 1.0f);
  EXPECT_GE(tiny.parts[1].index_count, 3u);
  EXPECT_EQ(tiny.parts[0].index_count, full.parts[0].index_count);  // cards are never thinned
  // Simplified vertices stay on (near) the sphere.
  for (uint32_t i = quarter.parts[1].first_index; i < quarter.parts[1].first_index + quarter.parts[1].index_count; ++i)
    EXPECT_NEAR(quarter.positions[quarter.indices[i]].norm(), 1.0f, 1e-4f);
}

TEST(Lod, ChainIsStrictlyDecreasingAndStopsWhenNothingToRemove) {
  const LodChain chain = build_lods(sphere_and_cards(8));
  const std::vector<Mesh>& lods = chain.lods;
  ASSERT_EQ(lods.size(), 4u);
  EXPECT_EQ(chain.screen_sizes, std::vector<float>(std::begin(kLodScreenSizes), std::end(kLodScreenSizes)));
  for (size_t k = 1; k < lods.size(); ++k) EXPECT_LT(lods[k].triangle_count(), lods[k - 1].triangle_count());
  MeshBuilder b;
  b.begin_part(Role::GroundVegetation, Material::Grass, grass_tuft_mask(), true);
  add_card(b, Vec3f::Zero(), Vec3f::UnitX(), Vec3f::UnitZ());
  const LodChain cards = build_lods(b.finish());  // cards are never reduced
  EXPECT_EQ(cards.lods.size(), 1u);
  EXPECT_TRUE(cards.screen_sizes.empty());
}

}  // namespace
}  // namespace silva::assets
