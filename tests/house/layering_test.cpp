// The layering of docs/DESIGN.md's folder table, enforced on every #include and CMake link line of
// our sources, the table itself kept acyclic and within the layering pinned in pinned_layers.cpp.
#include <gtest/gtest.h>

#include <sstream>

#include "design_table.hpp"
#include "include_lines.hpp"
#include "link_lines.hpp"
#include "pinned_layers.hpp"
#include "rule_graph.hpp"
#include "source_tree.hpp"

namespace silva::house {
namespace {

TEST(Layering, EveryIncludeIsAllowed) {
  const std::vector<FolderRule> rules = design_rules(source_root());
  ASSERT_FALSE(rules.empty()) << "docs/DESIGN.md has no folder table rows of the form | `folder/` | ... | ... |";
  const std::string violations = include_violations(source_root(), rules);
  EXPECT_TRUE(violations.empty()) << violations << "\n" << format_rules(rules);
}

TEST(Layering, EveryLinkLineIsAllowed) {
  const std::vector<FolderRule> rules = design_rules(source_root());
  ASSERT_FALSE(link_lines(source_root()).empty()) << "no link line between our libraries found in the CMake files";
  const std::string violations = link_violations(source_root(), rules);
  EXPECT_TRUE(violations.empty()) << violations << "\n" << format_rules(rules);
}

TEST(Layering, TableIsAcyclic) {
  const std::vector<FolderRule> rules = design_rules(source_root());
  EXPECT_EQ(find_cycle(rules), "") << format_rules(rules);
}

TEST(Layering, TableStaysWithinThePinnedLayers) {
  const std::vector<FolderRule> rules = design_rules(source_root());
  const std::string loosened = loosened_edges(rules);
  EXPECT_TRUE(loosened.empty()) << loosened << "loosening the layering takes tests/house/pinned_layers.cpp too\n";
}

TEST(Layering, NoEcsOutsideTheEcsLayers) {
  std::ostringstream out;
  for (const char* folder : {"world", "render", "io", "assets", "core"}) {
    for (const Include& inc : source_includes(source_root(), folder)) {
      if (inc.folder == "ecs") out << inc.file << ":" << inc.line << ": " << inc.text << "\n";
    }
  }
  EXPECT_TRUE(out.str().empty()) << "world/, render/, io/, assets/ and core/ are usable without the ECS:\n" << out.str();
}

}  // namespace
}  // namespace silva::house
