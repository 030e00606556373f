#pragma once
/// @file The season of a world: leaf colour, bare deciduous trees in winter, spring flowers.
#include <string_view>

namespace silva {

/// Season of the vegetation (config vegetation.season).
enum class Season : unsigned char {
  Summer,  ///< Green leaves.
  Autumn,  ///< Deciduous leaves, larch needles and ferns turn yellow, orange and brown.
  Winter,  ///< Deciduous trees and shrubs bare (twig cards instead of leaves), ferns dead brown.
  Spring,  ///< Young light green leaves; wood anemone carpets in flower.
  EarlySpring,  ///< Crowns still bare and last year's ferns and grass dead, as in winter; wood anemone in flower.
};

/// The config name of a season ("summer", "autumn", "winter", "spring", "early_spring").
std::string_view season_name(Season s);

/// Parses a season name; false when unknown.
bool parse_season(std::string_view name, Season& out);

}  // namespace silva
