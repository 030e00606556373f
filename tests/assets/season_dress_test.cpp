// Seasons: the same tree shapes, dressed in young spring leaves, autumn colours or bare twigs in winter.
#include "assets/season_dress.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "assets/alpha_masks.hpp"
#include "assets/factory.hpp"
#include "assets/foliage_sprays.hpp"
#include "assets/understory_masks.hpp"

namespace silva::assets {
namespace {

/// Variant 3 of the built-in generator `prefix` for `season`.
Mesh variant(const char* prefix, Season season) {
  const Factory* f = find_factory(prefix);
  EXPECT_NE(f, nullptr) << prefix;
  return generate_variant(*f, kDefaultAssetSeed, 3, season).mesh;
}

/// The mesh's card (masked) parts.
std::vector<MeshPart> cards(const Mesh& m) {
  std::vector<MeshPart> out;
  for (const MeshPart& p : m.parts)
    if (p.mask) out.push_back(p);
  return out;
}

TEST(SeasonDress, ShapesNeverDependOnTheSeason) {
  for (const char* prefix : {"beech", "larch", "spruce", "hazel", "fern", "nettle", "wood_sorrel"}) {
    const Mesh summer = variant(prefix, Season::Summer);
    for (Season s : {Season::Autumn, Season::Winter, Season::Spring, Season::EarlySpring}) {
      if (s == Season::EarlySpring && std::string(prefix) == "fern") continue;  // laid flat: the next test
      if (s == Season::Spring && find_factory(prefix)->young) continue;        // young: young_plants_test.cpp
      const Mesh dressed = variant(prefix, s);
      EXPECT_EQ(dressed.positions, summer.positions) << prefix;
      EXPECT_EQ(dressed.indices, summer.indices) << prefix;
      ASSERT_EQ(dressed.parts.size(), summer.parts.size()) << prefix;
      for (size_t k = 0; k < summer.parts.size(); ++k) EXPECT_EQ(dressed.parts[k].role, summer.parts[k].role);
    }
  }
}

TEST(SeasonDress, AutumnTurnsDeciduousLeavesLarchNeedlesAndFerns) {
  ASSERT_FALSE(cards(variant("beech", Season::Autumn)).empty());
  for (const MeshPart& p : cards(variant("beech", Season::Autumn))) EXPECT_EQ(p.material, Material::AutumnLeaves);
  for (const MeshPart& p : cards(variant("hazel", Season::Autumn))) EXPECT_EQ(p.material, Material::AutumnLeaves);
  for (const MeshPart& p : cards(variant("larch", Season::Autumn))) EXPECT_EQ(p.material, Material::AutumnNeedles);
  for (const MeshPart& p : cards(variant("spruce", Season::Autumn))) EXPECT_EQ(p.material, Material::NeedlesSpruce);
  ASSERT_FALSE(cards(variant("fern", Season::Autumn)).empty());
  for (const MeshPart& p : cards(variant("fern", Season::Autumn))) EXPECT_EQ(p.material, Material::AutumnLeaves);
  ASSERT_FALSE(cards(variant("grass", Season::Autumn)).empty());
  for (const MeshPart& p : cards(variant("grass", Season::Autumn))) EXPECT_EQ(p.material, Material::AutumnGrass);
}

TEST(SeasonDress, SpringGivesDeciduousCrownsYoungLeavesAndLeavesEvergreensAndGrassAsInSummer) {
  for (const char* prefix : {"beech", "birch", "oak", "larch", "hazel"}) {
    const std::vector<MeshPart> summer = cards(variant(prefix, Season::Summer));
    const std::vector<MeshPart> spring = cards(variant(prefix, Season::Spring));
    ASSERT_FALSE(spring.empty()) << prefix;
    ASSERT_EQ(spring.size(), summer.size()) << prefix;
    for (size_t k = 0; k < spring.size(); ++k) {
      EXPECT_EQ(spring[k].material, Material::SpringLeaves) << prefix;
      EXPECT_EQ(spring[k].mask, summer[k].mask) << prefix;  // leaves, not twigs: the same crowns as in summer
    }
  }
  for (const char* prefix : {"spruce", "pine", "grass", "wood_sorrel"}) {  // young ferns: young_plants_test.cpp
    const std::vector<MeshPart> summer = cards(variant(prefix, Season::Summer));
    const std::vector<MeshPart> spring = cards(variant(prefix, Season::Spring));
    ASSERT_EQ(spring.size(), summer.size()) << prefix;
    for (size_t k = 0; k < spring.size(); ++k) EXPECT_EQ(spring[k].material, summer[k].material) << prefix;
  }
}

TEST(SeasonDress, EarlySpringIsDressedAsWinter) {
  for (const char* prefix : {"beech", "larch", "spruce", "hazel", "fern", "grass", "nettle", "wood_sorrel"}) {
    const Mesh winter = variant(prefix, Season::Winter), early = variant(prefix, Season::EarlySpring);
    ASSERT_EQ(early.parts.size(), winter.parts.size()) << prefix;
    for (size_t k = 0; k < winter.parts.size(); ++k) {
      const bool matted = winter.parts[k].material == Material::DeadBracken && early.parts[k].mask == pinnate_frond_mask();
      EXPECT_EQ(early.parts[k].material, matted ? Material::MattedBracken : winter.parts[k].material) << prefix;
      EXPECT_EQ(early.parts[k].mask, winter.parts[k].mask) << prefix;
    }
  }
}

TEST(SeasonDress, EarlySpringLaysLastYearsBrackenFlat) {
  const Mesh summer = variant("fern", Season::Summer), early = variant("fern", Season::EarlySpring);
  ASSERT_EQ(early.positions.size(), summer.positions.size());
  EXPECT_EQ(early.indices, summer.indices);
  float summer_top = 0, early_top = 0, summer_reach = 0, early_reach = 0;
  for (size_t k = 0; k < summer.positions.size(); ++k) {
    summer_top = std::max(summer_top, summer.positions[k].z());
    early_top = std::max(early_top, early.positions[k].z());
    summer_reach = std::max(summer_reach, summer.positions[k].head<2>().norm());
    early_reach = std::max(early_reach, early.positions[k].head<2>().norm());
  }
  EXPECT_GT(summer_top, 0.15f);  // the smallest class of bracken stands 18 cm or more
  EXPECT_NEAR(early_top, kFlatBrackenHeight * summer_top, 1e-5f);
  EXPECT_NEAR(early_reach, kFlatBrackenSpread * summer_reach, 1e-4f);
  // A flattened frond faces up more than a standing one: its normals' mean |z| grows.
  double up_summer = 0, up_early = 0;
  for (size_t k = 0; k < summer.normals.size(); ++k) {
    up_summer += std::abs(summer.normals[k].z());
    up_early += std::abs(early.normals[k].z());
    EXPECT_NEAR(early.normals[k].norm(), 1.0f, 1e-5f);
  }
  EXPECT_GT(up_early, 1.2 * up_summer);
  EXPECT_EQ(variant("fern", Season::Winter).positions, summer.positions);  // in winter it still stands
  ASSERT_FALSE(cards(early).empty());  // lying on the litter it is rust-brown; nettle stems still stand grey-brown
  for (const MeshPart& p : cards(early)) EXPECT_EQ(p.material, Material::MattedBracken);
  for (const MeshPart& p : cards(variant("nettle", Season::EarlySpring))) EXPECT_EQ(p.material, Material::DeadBracken);
}

TEST(SeasonDress, WinterFernsAreDeadBrackenAndGrassIsDry) {
  for (const char* prefix : {"fern", "nettle"}) {  // nettle stands die back to grey-brown stems and leaves too
    ASSERT_FALSE(cards(variant(prefix, Season::Winter)).empty()) << prefix;
    for (const MeshPart& p : cards(variant(prefix, Season::Winter))) EXPECT_EQ(p.material, Material::DeadBracken) << prefix;
  }
  ASSERT_FALSE(cards(variant("grass", Season::Winter)).empty());
  for (const MeshPart& p : cards(variant("grass", Season::Winter))) EXPECT_EQ(p.material, Material::WinterGrass);
}

TEST(SeasonDress, ForestHerbsStayGreenThroughTheYear) {
  for (const char* prefix : {"wood_sorrel", "woodruff", "wood_anemone"})
    for (Season s : {Season::Summer, Season::Autumn, Season::Winter, Season::Spring, Season::EarlySpring}) {
      const Mesh m = variant(prefix, s);
      ASSERT_FALSE(m.parts.empty()) << prefix;
      for (const MeshPart& p : m.parts)  // the anemone's flowers keep their petals
        EXPECT_EQ(p.material, p.mask == wood_anemone_flower_mask() ? Material::Petals : Material::Herb) << prefix;
    }
}

TEST(SeasonDress, WinterLeavesDeciduousCrownsBareAndEvergreensGreen) {
  for (const char* prefix : {"beech", "birch", "oak", "larch", "hazel"}) {
    const std::vector<MeshPart> summer = cards(variant(prefix, Season::Summer));
    const std::vector<MeshPart> winter = cards(variant(prefix, Season::Winter));
    ASSERT_EQ(winter.size(), summer.size()) << prefix;
    for (size_t k = 0; k < winter.size(); ++k) {
      EXPECT_EQ(winter[k].material, Material::BareTwigs) << prefix;
      // Trees: twigs drawn for the same card size as the leaves they replace; the hazel: the small twig mask.
      const auto twigs = bare_twigs_for(summer[k].mask.get());
      EXPECT_EQ(winter[k].mask, prefix == std::string("hazel") ? bare_twig_mask() : twigs) << prefix;
      if (prefix != std::string("hazel")) {
        EXPECT_NE(twigs, nullptr) << prefix;
      }
    }
  }
  const Mesh summer = variant("pine", Season::Summer), winter = variant("pine", Season::Winter);
  ASSERT_EQ(cards(winter).size(), cards(summer).size());
  for (size_t k = 0; k < cards(winter).size(); ++k) {
    EXPECT_EQ(cards(winter)[k].material, cards(summer)[k].material);
    EXPECT_EQ(cards(winter)[k].mask, cards(summer)[k].mask);
  }
}

TEST(SeasonDress, NamesRoundTrip) {
  for (Season s : {Season::Summer, Season::Autumn, Season::Winter, Season::Spring, Season::EarlySpring}) {
    Season parsed = Season::Summer;
    ASSERT_TRUE(parse_season(season_name(s), parsed));
    EXPECT_EQ(parsed, s);
  }
  Season unused = Season::Summer;
  EXPECT_FALSE(parse_season("monsoon", unused));
  EXPECT_FALSE(parse_season("Spring", unused));
}

}  // namespace
}  // namespace silva::assets
