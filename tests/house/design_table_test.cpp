// Known answers for reading docs/DESIGN.md's folder table.
#include <gtest/gtest.h>

#include "design_table.hpp"

namespace silva::house {
namespace {

constexpr const char* kTable = R"(| folder | what lives there | may include |
|---|---|---|
| `core/` | shared things. | std, Eigen |
| `render/` | pixels | core, Eigen, TBB |
| `systems/` | glue | core, ecs, render, io |
| `app/` | the CLI | everything above, CLI11 |
| `configs/` | data | |
)";

TEST(DesignTable, RowsOfSourceFoldersAreRead) {
  const std::vector<FolderRule> rules = parse_design_table(kTable);
  ASSERT_EQ(rules.size(), 4u);
  EXPECT_EQ(rules[0].folder, "core");
  EXPECT_TRUE(rules[0].allowed.empty());
  EXPECT_EQ(rules[1].may_include, "core, Eigen, TBB");
  EXPECT_EQ(allowed_list(rules[1]), "render, core");
  EXPECT_EQ(allowed_list(rules[2]), "systems, core, ecs, io, render");
  EXPECT_EQ(allowed_list(rules[3]), "app, core, render, systems");
  EXPECT_NE(format_rules(rules).find("render/: \"core, Eigen, TBB\" -> render, core"), std::string::npos);
}

TEST(DesignTable, AFolderWithoutARowAllowsOnlyItself) {
  const std::vector<FolderRule> rules = parse_design_table(kTable);
  EXPECT_EQ(allowed_list(rule_for(rules, "systems")), "systems, core, ecs, io, render");
  EXPECT_EQ(allowed_list(rule_for(rules, "web")), "web");
}

}  // namespace
}  // namespace silva::house
