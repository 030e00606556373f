#include "world/forest_types.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/rng.hpp"

namespace silva::world {

const std::vector<ForestType>& forest_types() {
  static const std::vector<ForestType> types = {
      // Mixed: every species; spruce is one of its three conifers.
      {.name = "mixed", .conifers = {}, .broadleaves = {}, .shrubs = {}, .herbs = {}, .spruce_litter = 1.0 / 3.0},
      // Even-aged Norway spruce: closed and dark, few shrubs, mostly bare needle litter with moss, ferns and
      // wood sorrel (no woodruff, nettle or wood anemone: acid needle litter).
      {.name = "spruce_plantation", .conifer_share = 1.0, .conifers = {"spruce"}, .broadleaves = {}, .shrubs = {},
       .herbs = {"fern", "wood_sorrel"}, .shrub_scale = 0.25,
       .ground_share = 0.35, .fern_bias = 0.15, .needle_litter = 1.0, .spruce_litter = 1.0},
      // Beech hall forest: tall beech over a bare leaf-litter floor, a little hazel, ferns, wood sorrel, woodruff and
      // in spring wood anemone, which then carpets much of the bare floor before the beech leaf out (no nettle: it
      // wants the light and nitrogen of open, rich ground).
      {.name = "beech_hall", .conifer_share = 0.0, .conifers = {}, .broadleaves = {"beech"}, .shrubs = {"hazel"},
       .herbs = {"fern", "wood_sorrel", "woodruff", "wood_anemone"}, .shrub_scale = 0.3, .ground_share = 0.15,
       .vernal_share = 0.8, .needle_litter = 0.0},
      // Pine heath: open Scots pine with some birch over bilberry, grass and ferns (no wood sorrel: dry, poor soil).
      {.name = "pine_heath", .conifer_share = 0.85, .conifers = {"pine"}, .broadleaves = {"birch"},
       .shrubs = {"bilberry"}, .herbs = {"fern"}, .shrub_scale = 3.0, .ground_share = 1.0, .fern_bias = -0.3, .needle_litter = 0.85},
  };
  return types;
}

const ForestType& forest_type_of(const std::string& name, uint64_t seed) {
  const auto& types = forest_types();
  if (name == "random") {
    Rng rng(seed, 0, Purpose::ForestType);
    return types[rng.below(uint32_t(types.size()))];
  }
  for (const ForestType& t : types)
    if (t.name == name) return t;
  std::string allowed;
  for (const ForestType& t : types) allowed += t.name + ", ";
  throw InputError("vegetation.forest_type = \"" + name + "\" is not a forest type (allowed: " + allowed + "random)");
}

bool grows(const std::vector<std::string>& list, const std::string& species) {
  return list.empty() || std::find(list.begin(), list.end(), species) != list.end();
}

bool vernal_herb(const std::string& species) { return species == "wood_anemone"; }

bool vernal_season(Season season) { return season == Season::Spring || season == Season::EarlySpring; }

bool shows_in(const std::string& species, Season season) { return !vernal_herb(species) || vernal_season(season); }

}  // namespace silva::world
