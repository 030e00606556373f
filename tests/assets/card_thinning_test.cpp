// Card thinning (the shadow caster's cards): a share of the cards, grown so their area stays.
#include "assets/card_thinning.hpp"

#include <gtest/gtest.h>

#include <set>

#include "assets/alpha_masks.hpp"
#include "assets/library.hpp"
#include "assets/lod.hpp"
#include "assets/mesh_builder.hpp"
#include "assets/strips.hpp"
#include "tests/assets/card_meshes.hpp"

namespace silva::assets {
namespace {

using test::row_of_cards;

/// Summed area of the triangles `indices` over `positions`.
double area(const std::vector<uint32_t>& indices, const std::vector<Vec3f>& positions) {
  double sum = 0;
  for (size_t t = 0; t + 2 < indices.size(); t += 3)
    sum += 0.5 * double((positions[indices[t + 1]] - positions[indices[t]])
                            .cross(positions[indices[t + 2]] - positions[indices[t]])
                            .norm());
  return sum;
}

TEST(CardThinning, KeepsAnEvenShareOfTheCardsAndTheirTotalArea) {
  const Mesh full = row_of_cards(10);
  std::vector<Vec3f> positions = full.positions;
  const std::vector<uint32_t> kept = thin_cards(full, full.parts[0], 0.3f, positions);
  ASSERT_EQ(kept.size(), 3u * 2u * 3u);  // round(10 x 0.3) = 3 cards of 2 triangles
  EXPECT_NEAR(area(kept, positions), 10.0, 1e-4);
  // The kept cards are spread out (not the first three) and keep their centres.
  std::set<int> centres;
  for (size_t t = 0; t < kept.size(); t += 6) {
    Vec3f c = Vec3f::Zero();
    for (size_t k = 0; k < 6; ++k) c += positions[kept[t + k]] / 6.0f;
    EXPECT_NEAR(c.y(), 0.0f, 1e-5f);
    EXPECT_NEAR(c.z(), 0.0f, 1e-5f);
    EXPECT_NEAR(c.x() / 3.0f, std::round(c.x() / 3.0f), 1e-5f);
    centres.insert(int(std::lround(c.x() / 3.0f)));
  }
  EXPECT_EQ(centres.size(), 3u);
  EXPECT_GE(*centres.rbegin() - *centres.begin(), 5);
}

TEST(CardThinning, KeepsAtLeastOneCardAndAllAtRatioOne) {
  const Mesh full = row_of_cards(4);
  std::vector<Vec3f> positions = full.positions;
  const std::vector<uint32_t> one = thin_cards(full, full.parts[0], 1e-6f, positions);
  EXPECT_EQ(one.size(), 6u);
  EXPECT_NEAR(area(one, positions), 4.0, 1e-4);
  std::vector<Vec3f> unchanged = full.positions;
  EXPECT_EQ(thin_cards(full, full.parts[0], 1.0f, unchanged).size(), full.indices.size());
  EXPECT_EQ(unchanged, full.positions);
}

TEST(CardThinning, CardsSharingVerticesWithAnotherPartStayWhole) {
  Mesh m = row_of_cards(4);
  MeshPart solid;  // a second part reusing the first card's vertices
  solid.first_index = uint32_t(m.indices.size());
  solid.index_count = 3;
  solid.role = Role::TreeTrunk;
  solid.material = Material::BarkBroadleaf;
  m.indices.insert(m.indices.end(), {0u, 1u, 2u});
  m.parts.push_back(solid);
  std::vector<Vec3f> positions = m.positions;
  EXPECT_EQ(thin_cards(m, m.parts[0], 0.25f, positions).size(), size_t(m.parts[0].index_count));
}

TEST(ShadowCaster, IsLodOneWithItsCardsThinned) {
  const Mesh full = test::cards_and_sphere(40, Role::TreeTrunk, Material::BarkBroadleaf);
  const AssetGeometry geometry(build_lods(full).lods);
  ASSERT_GE(geometry.lods().size(), 2u);
  const Mesh& lod1 = geometry.lods()[1];
  const Mesh& caster = geometry.shadow_caster();
  ASSERT_EQ(caster.parts.size(), 2u);
  EXPECT_EQ(caster.parts[0].index_count, uint32_t(std::lround(40 * kShadowCardRatio)) * 6u);
  EXPECT_EQ(caster.parts[1].index_count, lod1.parts[1].index_count);
  EXPECT_LT(caster.parts[1].index_count, full.parts[1].index_count);
  EXPECT_EQ(caster.parts[1].role, Role::TreeTrunk);
  EXPECT_EQ(&geometry.shadow_caster(), &caster);  // made once

  const Mesh sphere = unit_icosphere(3);
  const AssetGeometry solid_only(std::vector<Mesh>{sphere});
  EXPECT_EQ(&solid_only.shadow_caster(), &solid_only.lods()[0]);
}

}  // namespace
}  // namespace silva::assets
