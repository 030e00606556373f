/// @file docs/DESIGN.md's folder table ("| `folder/` | what lives there | may include |") read as rules.
#pragma once

#include <filesystem>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace silva::house {

/// One row of the folder table: a source folder and the source folders it may include.
struct FolderRule {
  std::string folder;            ///< e.g. "render"
  std::string may_include;       ///< the third cell as written, e.g. "core, Eigen, TBB, Highway"
  std::set<std::string> allowed; ///< our source folders named there (the folder itself is always allowed too)
};

/// The rows of `markdown` whose first cell is a `source folder/`, in table order. In the third
/// cell, words that name source folders are the allowed ones; "everything above" allows every
/// source folder of the rows before it.
std::vector<FolderRule> parse_design_table(std::string_view markdown);

/// The rules as a small table, one folder a line, for failure messages.
std::string format_rules(const std::vector<FolderRule>& rules);

/// The folder and its allowed folders, comma-separated ("render, core").
std::string allowed_list(const FolderRule& rule);

/// The rules of root/docs/DESIGN.md's folder table.
std::vector<FolderRule> design_rules(const std::filesystem::path& root);

/// The row of `folder`, or a row allowing nothing but itself when the table has none.
FolderRule rule_for(const std::vector<FolderRule>& rules, std::string_view folder);

}  // namespace silva::house
