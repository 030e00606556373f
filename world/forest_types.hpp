#pragma once
/// @file Forest types (vegetation.forest_type): which species grow where the placement grid holds
/// a tree or a shrub, and how much shrub layer and ground vegetation grow under them.
#include <cstdint>
#include <string>
#include <vector>

#include "core/season.hpp"

namespace silva::world {

/// What one forest type grows. Species are asset generators (`spruce`, `beech`, `bilberry`, ...);
/// an empty list grows every species of the kind, user (file) assets always.
struct ForestType {
  std::string name;                      ///< Its vegetation.forest_type value.
  double conifer_share = 0.5;            ///< Share of tree points that hold conifers (the rest broadleaves).
  std::vector<std::string> conifers;     ///< Conifer species grown.
  std::vector<std::string> broadleaves;  ///< Broadleaf species grown.
  std::vector<std::string> shrubs;       ///< Shrub species grown.
  std::vector<std::string> herbs;        ///< Fern-layer species grown (`fern`, `wood_sorrel`, `woodruff`, `nettle`, `wood_anemone`).
  double shrub_scale = 1.0;              ///< Factor on the share of points that hold a shrub.
  double ground_share = 1.0;             ///< Share of ground-vegetation points with grass and ferns (the rest bare litter).
  /// Share of ground-vegetation points that are not bare in spring and early spring, when vernal herbs (vernal_herb)
  /// carpet part of the floor that is bare litter the rest of the year; at most ground_share: none.
  double vernal_share = 0.0;
  double fern_bias = 0.0;                ///< Added to the share of ferns among those tufts (kept within 0 … 1).
  /// Share of needles in the floor's litter everywhere (render/materials.hpp FloorLook); negative:
  /// stands of needle and of leaf litter across the world.
  double needle_litter = -1.0;
  /// Share of the needle litter that falls from spruce, which lays its cones among it (FloorLook::spruce_cones).
  double spruce_litter = 0.0;
};

/// The named types, `mixed` (every species, the default) first, then `spruce_plantation`,
/// `beech_hall` and `pine_heath`.
const std::vector<ForestType>& forest_types();

/// The type vegetation.forest_type = `name` grows: a named type, or for `random` one of the named
/// types drawn from `seed` (each equally likely). Throws InputError for any other name.
const ForestType& forest_type_of(const std::string& name, uint64_t seed);

/// True when `species` (an asset generator) is in `list`, or `list` is empty.
bool grows(const std::vector<std::string>& list, const std::string& species);

/// Whether built-in species `species` shows above ground in `season`: wood anemone only in spring and early spring
/// (it leafs and flowers before the canopy closes and dies back by early summer), every other species all year.
bool shows_in(const std::string& species, Season season);

/// True for a built-in species that grows above ground only in spring (`wood_anemone`): a vernal herb.
bool vernal_herb(const std::string& species);

/// True in the seasons vernal herbs show: spring and early spring.
bool vernal_season(Season season);

}  // namespace silva::world
