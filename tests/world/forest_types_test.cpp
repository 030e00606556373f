// Forest types: named and drawn types, the mix each gives, and the species each world grows.
#include "world/forest_types.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "assets/factory.hpp"
#include "core/error.hpp"
#include "world/class_mix.hpp"
#include "world/world_generator.hpp"
#include "tests/common/test_library.hpp"

namespace silva::world {
namespace {

/// The procedural library (species named by their generators), built once.
const assets::AssetLibrary& library() {
  static const assets::AssetLibrary lib = assets::generate_library();
  return lib;
}

TEST(ForestTypes, NamedTypesAndADrawPerSeed) {
  std::vector<std::string> names;
  for (const ForestType& t : forest_types()) names.push_back(t.name);
  EXPECT_EQ(names, (std::vector<std::string>{"mixed", "spruce_plantation", "beech_hall", "pine_heath"}));
  EXPECT_EQ(forest_type_of("beech_hall", 7).name, "beech_hall");
  std::set<std::string> drawn;
  for (uint64_t seed = 0; seed < 64; ++seed) {
    drawn.insert(forest_type_of("random", seed).name);
    EXPECT_EQ(&forest_type_of("random", seed), &forest_type_of("random", seed));
  }
  EXPECT_EQ(drawn.size(), forest_types().size());
  EXPECT_THROW(forest_type_of("jungle", 1), InputError);
}

TEST(ForestTypes, MixedKeepsTheDefaultMix) {
  const ClassMix m = class_mix(5, true, forest_types().front());
  EXPECT_EQ(m, class_mix(5, true));
  EXPECT_DOUBLE_EQ(m[size_t(PointClass::Conifer)], 0.025);
  EXPECT_DOUBLE_EQ(m[size_t(PointClass::Broadleaf)], 0.025);
  EXPECT_DOUBLE_EQ(m[size_t(PointClass::Shrub)], 0.06);
  EXPECT_EQ(m[size_t(PointClass::Nothing)], 0.0);
  const ClassMix beech = class_mix(5, true, forest_type_of("beech_hall", 0));
  EXPECT_EQ(beech[size_t(PointClass::Conifer)], 0.0);
  EXPECT_DOUBLE_EQ(beech[size_t(PointClass::Broadleaf)], 0.05);
  EXPECT_LT(beech[size_t(PointClass::Ground)], 0.2 * m[size_t(PointClass::Ground)]);
  double sum = 0;
  for (double p : beech) sum += p;
  EXPECT_NEAR(sum, 1.0, 1e-12);
  // In spring and early spring the beech hall's vernal herbs take floor that is bare in the other seasons.
  EXPECT_EQ(beech[size_t(PointClass::Vernal)], 0.0);
  EXPECT_EQ(class_mix(5, true, forest_type_of("beech_hall", 0), Season::Winter), beech);
  const ForestType& hall = forest_type_of("beech_hall", 0);
  for (Season s : {Season::Spring, Season::EarlySpring}) {
    const ClassMix spring = class_mix(5, true, hall, s);
    const double free = spring[size_t(PointClass::Ground)] / hall.ground_share;  // points not held by a solid
    EXPECT_EQ(spring[size_t(PointClass::Ground)], beech[size_t(PointClass::Ground)]);
    EXPECT_NEAR(spring[size_t(PointClass::Vernal)], free * (hall.vernal_share - hall.ground_share), 1e-12);
    EXPECT_NEAR(spring[size_t(PointClass::Nothing)], free * (1.0 - hall.vernal_share), 1e-12);
    EXPECT_EQ(class_mix(5, false, hall, s)[size_t(PointClass::Vernal)], 0.0);
  }
  EXPECT_EQ(class_mix(5, true, forest_types().front(), Season::Spring), m);  // the mixed stand has no bare floor
}

/// Objects of a 3 x 3 chunk world of forest type `type` in `season`: count per (kind, species), and
/// ground-vegetation count.
std::pair<std::map<std::pair<AssetKind, std::string>, int>, int> grown(const std::string& type,
                                                                       const std::string& season = "summer") {
  Config cfg = test::small_world_config(3, 8);
  cfg.vegetation.forest_type = type;
  cfg.vegetation.season = season;
  const WorldContext ctx = make_world_context(cfg, library());
  std::map<std::pair<AssetKind, std::string>, int> count;
  int ground = 0;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (const Vegetation& v : generate_chunk(ctx, ChunkCoord{i, j}).objects) {
        const assets::Asset& a = library().assets[v.asset];
        ++count[{a.kind, a.source ? a.source->generator : std::string()}];
        ground += a.kind == AssetKind::Grass || a.kind == AssetKind::Fern;
      }
  return {count, ground};
}

TEST(ForestTypes, EachTypeGrowsOnlyItsSpeciesAndItsUnderstory) {
  const auto [mixed, mixed_ground] = grown("mixed");
  for (const ForestType& t : forest_types()) {
    if (t.name == "mixed") continue;
    SCOPED_TRACE(t.name);
    const auto [count, ground] = grown(t.name);
    int trees = 0;
    for (const auto& [key, n] : count) {
      const auto& [kind, species] = key;
      const std::vector<std::string>* list = kind == AssetKind::ConiferTree     ? &t.conifers
                                             : kind == AssetKind::BroadleafTree ? &t.broadleaves
                                             : kind == AssetKind::Shrub         ? &t.shrubs
                                             : kind == AssetKind::Fern          ? &t.herbs
                                                                                : nullptr;
      EXPECT_TRUE(list == nullptr || grows(*list, species)) << species;
      trees += kind == AssetKind::ConiferTree || kind == AssetKind::BroadleafTree ? n : 0;
    }
    EXPECT_GT(trees, 20);
    EXPECT_TRUE(t.ground_share >= 0.5 || ground < mixed_ground * 0.6) << ground << " of " << mixed_ground;  // bare floors
  }
  // The mixed stand grows every tree species.
  std::set<std::string> species;
  for (const auto& [key, n] : mixed)
    if (key.first == AssetKind::ConiferTree || key.first == AssetKind::BroadleafTree) species.insert(key.second);
  EXPECT_EQ(species.size(), 6u);
  // Wood sorrel, woodruff and nettle grow beside the ferns in the mixed stand; none of them on the pine heath,
  // no woodruff or nettle under spruce, no nettle in the beech hall.
  EXPECT_GT(mixed.count({AssetKind::Fern, "wood_sorrel"}), 0u);
  EXPECT_GT(mixed.count({AssetKind::Fern, "woodruff"}), 0u);
  EXPECT_GT(mixed.count({AssetKind::Fern, "fern"}), 0u);
  EXPECT_GT(mixed.count({AssetKind::Fern, "nettle"}), 0u);
  for (const char* forest : {"pine_heath", "spruce_plantation", "beech_hall"})
    EXPECT_FALSE(grows(forest_type_of(forest, 0).herbs, "nettle")) << forest;
  EXPECT_FALSE(grows(forest_type_of("pine_heath", 0).herbs, "wood_sorrel"));
  EXPECT_FALSE(grows(forest_type_of("pine_heath", 0).herbs, "woodruff"));
  EXPECT_FALSE(grows(forest_type_of("spruce_plantation", 0).herbs, "woodruff"));
  EXPECT_TRUE(grows(forest_type_of("beech_hall", 0).herbs, "woodruff"));
}

TEST(ForestTypes, WoodAnemoneCarpetsTheMixedStandAndTheBeechHallInSpringAndEarlySpringOnly) {
  for (const char* forest : {"mixed", "beech_hall"}) {
    SCOPED_TRACE(forest);
    EXPECT_EQ(grown(forest).first.count({AssetKind::Fern, "wood_anemone"}), 0u);
    EXPECT_EQ(grown(forest, "autumn").first.count({AssetKind::Fern, "wood_anemone"}), 0u);
    const auto spring = grown(forest, "spring").first;
    const auto anemone = spring.find({AssetKind::Fern, "wood_anemone"});
    ASSERT_NE(anemone, spring.end());
    EXPECT_GT(anemone->second, 10);
    EXPECT_EQ(grown(forest, "early_spring").first.at({AssetKind::Fern, "wood_anemone"}), anemone->second);
  }
  // Under the beech the anemone carpets floor that is bare litter the rest of the year: it outnumbers the other
  // herbs together, and the hall's ground vegetation more than triples.
  const auto beech = grown("beech_hall", "spring").first;
  int others = 0;
  for (const char* herb : {"fern", "wood_sorrel", "woodruff"})
    if (beech.count({AssetKind::Fern, herb})) others += beech.at({AssetKind::Fern, herb});
  EXPECT_GT(beech.at({AssetKind::Fern, "wood_anemone"}), 2 * others);
  EXPECT_GT(grown("beech_hall", "spring").second, 3 * grown("beech_hall").second);
  for (const char* forest : {"pine_heath", "spruce_plantation"})  // dry heath and acid needle litter
    EXPECT_EQ(grown(forest, "spring").first.count({AssetKind::Fern, "wood_anemone"}), 0u) << forest;
  EXPECT_TRUE(shows_in("fern", Season::Winter));
  EXPECT_FALSE(shows_in("wood_anemone", Season::Summer));
  EXPECT_TRUE(shows_in("wood_anemone", Season::Spring));
  EXPECT_TRUE(shows_in("wood_anemone", Season::EarlySpring));
  EXPECT_FALSE(shows_in("wood_anemone", Season::Winter));
}

}  // namespace
}  // namespace silva::world
