// Known answers for cycles of the folder table and for the pinned layering.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "pinned_layers.hpp"
#include "rule_graph.hpp"
#include "source_tree.hpp"

namespace silva::house {
namespace {

TEST(RuleGraph, ACycleIsReported) {
  const std::vector<FolderRule> rules = parse_design_table(R"(| `core/` | a | std |
| `render/` | b | core, io |
| `io/` | c | core, world |
| `world/` | d | core, render |
)");
  EXPECT_EQ(find_cycle(rules), "render -> io -> world -> render");
}

TEST(RuleGraph, ATableWithoutCycleHasNone) {
  const std::vector<FolderRule> rules = parse_design_table(R"(| `core/` | a | std |
| `render/` | b | core |
| `io/` | c | core, render |
| `app/` | d | everything above |
)");
  EXPECT_EQ(find_cycle(rules), "");
}

TEST(PinnedLayers, PointDownwardsAndCoverEverySourceFolder) {
  std::set<std::string> below;
  for (const FolderRule& pin : pinned_rules()) {
    for (const std::string& x : pin.allowed) EXPECT_EQ(below.count(x), 1u) << pin.folder << " -> " << x << " points up";
    below.insert(pin.folder);
  }
  EXPECT_EQ(below, std::set<std::string>(std::begin(kSourceFolders), std::end(kSourceFolders)));
}

TEST(PinnedLayers, EdgesBeyondThePinsAreReported) {
  const std::vector<FolderRule> rules = parse_design_table(R"(| `core/` | a | std |
| `raycast/` | b | core, render |
| `render/` | c | core |
| `bench/` | d | everything above, app |
)");
  EXPECT_EQ(loosened_edges(rules),
            "docs/DESIGN.md: raycast/ may include render/, beyond the pinned layering (at most: raycast, core)\n"
            "docs/DESIGN.md: bench/ may include app/, beyond the pinned layering (at most: bench, assets, components, "
            "core, ecs, io, pipeline, raycast, render, systems, world)\n");
  EXPECT_EQ(loosened_edges(pinned_rules()), "");
}

}  // namespace
}  // namespace silva::house
