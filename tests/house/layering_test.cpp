// The layering of docs/DESIGN.md's folder table, enforced on every #include of our sources.
#include <gtest/gtest.h>

#include <sstream>

#include "design_table.hpp"
#include "source_tree.hpp"

namespace silva::house {
namespace {

std::vector<FolderRule> design_rules() { return parse_design_table(read_text(source_root() / "docs/DESIGN.md")); }

// "file:line includes X/ (allowed: ...)" for each include of `rule.folder`'s sources it does not allow.
std::string violations_of(const FolderRule& rule) {
  std::ostringstream out;
  for (const auto& file : source_files(source_root(), rule.folder)) {
    const std::vector<std::string> lines = split_lines(read_text(file));
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const std::string x = included_source_folder(lines[i]);
      if (x.empty() || x == rule.folder || rule.allowed.count(x) != 0) continue;
      out << shown(file) << ":" << i + 1 << " includes " << x << "/ (allowed: " << allowed_list(rule) << ")\n";
    }
  }
  return out.str();
}

TEST(Layering, EveryIncludeIsAllowed) {
  const std::vector<FolderRule> rules = design_rules();
  ASSERT_FALSE(rules.empty()) << "docs/DESIGN.md has no folder table rows of the form | `folder/` | ... | ... |";
  std::string violations;
  for (const FolderRule& rule : rules) violations += violations_of(rule);
  EXPECT_TRUE(violations.empty()) << violations << "\n" << format_rules(rules);
}

TEST(Layering, NoEcsOutsideTheEcsLayers) {
  std::ostringstream out;
  for (const char* folder : {"world", "render", "io", "assets", "core"}) {
    for (const auto& file : source_files(source_root(), folder)) {
      const std::vector<std::string> lines = split_lines(read_text(file));
      for (std::size_t i = 0; i < lines.size(); ++i) {
        if (included_source_folder(lines[i]) == "ecs") out << shown(file) << ":" << i + 1 << ": " << lines[i] << "\n";
      }
    }
  }
  EXPECT_TRUE(out.str().empty()) << "world/, render/, io/, assets/ and core/ are usable without the ECS:\n" << out.str();
}

}  // namespace
}  // namespace silva::house
