/// @file The #include lines of our sources that name one of our folders, and those the folder table does not allow.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "design_table.hpp"

namespace silva::house {

/// One #include line of a source file that reaches one of our source folders.
struct Include {
  std::string file;    ///< the including file, relative to the root, '/'-separated ("render/shade.cpp")
  std::size_t line;    ///< 1-based
  std::string text;    ///< the line as written
  std::string folder;  ///< the source folder it reaches ("core")
};

/// The source folder an #include `line` of `file` (relative to the repository root) reaches, or
/// empty: `<X/...>`, `"X/..."` with X ours, `"tests/..."` from the root (on the include path); other
/// quoted paths, "../" ones included, from the including file's folder, as the compiler tries first.
std::string included_source_folder(std::string_view file, std::string_view line);

/// Every #include of root/folder's sources that reaches one of our folders, in file and line order.
std::vector<Include> source_includes(const std::filesystem::path& root, std::string_view folder);

/// "file:line includes X/ (allowed: ...)" for each include of a source folder under `root` into
/// another folder that its row of `rules` does not allow (a folder without a row allows none).
std::string include_violations(const std::filesystem::path& root, const std::vector<FolderRule>& rules);

}  // namespace silva::house
