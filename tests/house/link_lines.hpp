/// @file The direct link lines between our CMake libraries, checked against the folder table.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "design_table.hpp"

namespace silva::house {

/// One library linking one of ours directly: `silva_library(name dir deps...)` or `target_link_libraries`.
struct LinkLine {
  std::string file;            ///< the CMake file, relative to the root ("bench/CMakeLists.txt")
  std::string library;         ///< the linking target ("silva_raycast")
  std::string library_folder;  ///< its source folder ("raycast")
  std::string dep;             ///< the linked library ("silva_core")
  std::string dep_folder;      ///< its source folder ("core")
};

/// The links between libraries of our folders in root/CMakeLists.txt and root/<folder>/CMakeLists.txt,
/// in order. A library's folder: a silva_library's directory's first segment, an add_library's in
/// <folder>/CMakeLists.txt that folder, else X of `silva_X` when X is a source folder; libraries of no
/// folder (silva_opencv, silva_fcl, TBB::tbb) are left out.
std::vector<LinkLine> link_lines(const std::filesystem::path& root);

/// "CMakeLists.txt: silva_raycast links silva_render (raycast/ may include: core)" for each link
/// between two folders that `rules` does not allow (a folder without a row allows none).
std::string link_violations(const std::filesystem::path& root, const std::vector<FolderRule>& rules);

}  // namespace silva::house
