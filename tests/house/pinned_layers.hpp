/// @file The layering pinned in the tests, so that loosening docs/DESIGN.md's table alone loosens nothing.
#pragma once

#include <string>
#include <vector>

#include "design_table.hpp"

namespace silva::house {

/// The pinned layers bottom up, as rules: each folder with the most it may ever include.
std::vector<FolderRule> pinned_rules();

/// "docs/DESIGN.md: F/ may include X/, beyond the pinned layering (...)" for each edge of `rules` the pins forbid.
std::string loosened_edges(const std::vector<FolderRule>& rules);

}  // namespace silva::house
