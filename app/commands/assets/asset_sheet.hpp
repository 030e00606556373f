#pragma once
/// @file Contact sheets of the built-in procedural assets (`silva assets sheet`): each variant is
/// rendered alone on a flat forest floor in daylight, RGB beside its semantic colours.
#include <cstdint>
#include <string>
#include <vector>

#include "assets/factory.hpp"

namespace silva::app {

/// Pixel size and content of a contact sheet.
struct SheetLayout {
  int cell = 320;     ///< Side of one square view (the RGB and the semantic view each), pixels.
  int columns = 3;    ///< Variants per row (each two cells wide).
};

/// The factories `names` selects, a comma-separated list of kind names ("conifer_tree": every
/// factory of the kind) and factory prefixes ("norway_spruce"); empty when one name is neither.
std::vector<const assets::Factory*> select_factories(const std::string& names);

/// Renders variants 0..count-1 of every factory in `factories` (asset seed `seed`) into one
/// interleaved RGB8 image of `width` x `height`, row by row in factory order.
std::vector<uint8_t> render_asset_sheet(const std::vector<const assets::Factory*>& factories, int count, uint64_t seed,
                                        const SheetLayout& layout, int& width, int& height);

}  // namespace silva::app
