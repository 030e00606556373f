#include "world/species_stands.hpp"

#include <gtest/gtest.h>

namespace silva::world {
namespace {

/// A library of `per_generator` conifer variants from each of `generators`, plus one file rock.
assets::AssetLibrary two_species_library(std::initializer_list<const char*> generators, uint32_t per_generator) {
  assets::AssetLibrary lib;
  for (const char* g : generators)
    for (uint32_t v = 0; v < per_generator; ++v) {
      assets::Asset a;
      a.name = std::string(g) + std::to_string(v);
      a.kind = AssetKind::ConiferTree;
      a.source = assets::ProceduralSource{g, v, 1};
      lib.assets.push_back(a);
    }
  assets::Asset rock;
  rock.name = "rock";
  rock.file = "rock.glb";
  rock.kind = AssetKind::Rock;
  lib.assets.push_back(rock);
  lib.index_kinds();
  return lib;
}

TEST(SpeciesStands, GroupsAKindsAssetsByGenerator) {
  const SpeciesStands s = make_species_stands(two_species_library({"spruce", "pine"}, 3), 5);
  ASSERT_EQ(s.groups[size_t(AssetKind::ConiferTree)].size(), 2u);
  EXPECT_EQ(s.groups[size_t(AssetKind::ConiferTree)][0], (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(s.groups[size_t(AssetKind::ConiferTree)][1], (std::vector<uint32_t>{3, 4, 5}));
  ASSERT_EQ(s.groups[size_t(AssetKind::Rock)].size(), 1u);
  EXPECT_TRUE(s.groups[size_t(AssetKind::Fern)].empty());
  Rng rng(1, 2, Purpose::Test);
  EXPECT_EQ(pick_asset(s, AssetKind::Fern, 0, 0, rng), UINT32_MAX);
  EXPECT_EQ(pick_asset(s, AssetKind::Rock, 0, 0, rng), 6u);
}

/// Share of picks within a `size` m square at (x0, y0) that come from the first group.
double first_group_share(const SpeciesStands& s, double x0, double y0, double size) {
  int first = 0, n = 0;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j, ++n) {
      Rng rng(9, uint64_t(i * 20 + j), Purpose::Test);
      first += pick_asset(s, AssetKind::ConiferTree, x0 + size * i / 20.0, y0 + size * j / 20.0, rng) < 3 ? 1 : 0;
    }
  return double(first) / n;
}

TEST(SpeciesStands, OneSpeciesDominatesEachStandAndBothGrowAcrossTheWorld) {
  const SpeciesStands s = make_species_stands(two_species_library({"spruce", "pine"}, 3), 5);
  int spruce_stands = 0, pine_stands = 0;
  for (int k = 0; k < 12; ++k) {
    // A 4 m patch lies inside one stand: about kDominantShare + (1 - kDominantShare) / 2 of one species.
    const double share = first_group_share(s, 400.0 * k, -250.0 * k, 4.0);
    EXPECT_TRUE(share > 0.75 || share < 0.25) << "patch " << k << ": " << share;
    (share > 0.5 ? spruce_stands : pine_stands) += 1;
  }
  EXPECT_GE(spruce_stands, 2);
  EXPECT_GE(pine_stands, 2);
}

TEST(SpeciesStands, PicksAreAFunctionOfSeedPositionAndStream) {
  const auto lib = two_species_library({"spruce", "pine", "larch"}, 4);
  const SpeciesStands a = make_species_stands(lib, 5), b = make_species_stands(lib, 5), c = make_species_stands(lib, 6);
  int differ = 0;
  for (int k = 0; k < 50; ++k) {
    Rng r1(3, uint64_t(k), Purpose::Test), r2(3, uint64_t(k), Purpose::Test), r3(3, uint64_t(k), Purpose::Test);
    const uint32_t pa = pick_asset(a, AssetKind::ConiferTree, 37.0 * k, 11.0 * k, r1);
    EXPECT_EQ(pa, pick_asset(b, AssetKind::ConiferTree, 37.0 * k, 11.0 * k, r2));
    differ += pa != pick_asset(c, AssetKind::ConiferTree, 37.0 * k, 11.0 * k, r3) ? 1 : 0;
  }
  EXPECT_GT(differ, 5);  // another world seed moves the stands
}

}  // namespace
}  // namespace silva::world
