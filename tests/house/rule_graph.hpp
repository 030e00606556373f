/// @file The folder table read as a graph (folder -> the folders it may include): its cycles.
#pragma once

#include <string>
#include <vector>

#include "design_table.hpp"

namespace silva::house {

/// A cycle of the rules' allowed edges, written "a -> b -> a" (the first found, in table order), or empty.
std::string find_cycle(const std::vector<FolderRule>& rules);

}  // namespace silva::house
