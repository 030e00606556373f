// The layering checks on a tiny scratch repository that breaks them on purpose, one gap at a time.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <string>

#include "design_table.hpp"
#include "include_lines.hpp"
#include "link_lines.hpp"
#include "pinned_layers.hpp"
#include "rule_graph.hpp"
#include "../common/scratch_dirs.hpp"

namespace silva::house {
namespace {

namespace fs = std::filesystem;

constexpr const char* kTable = R"(| folder | what lives there | may include |
|---|---|---|
| `core/` | basics | std |
| `render/` | pixels | core, TBB |
| `app/` | the CLI | everything above |
)";

constexpr const char* kCMake = R"(silva_library(silva_core core Eigen3::Eigen)
silva_library(silva_render render
              silva_core silva_opencv)
silva_library(silva_app app silva_render)
)";

/// A scratch repository (core/, render/, app/) that keeps the layering until a test breaks it.
class LayeringFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    root_ = fs::temp_directory_path() /
            (std::string("silva-house-") + test->name() + "-" + std::to_string(std::random_device{}()));
    fs::remove_all(root_);
    silva::test::remove_when_passed(root_);
    write("docs/DESIGN.md", kTable);
    write("CMakeLists.txt", kCMake);
    write("core/base.hpp", "#pragma once\n");
    write("render/draw.cpp", "#include \"core/base.hpp\"\n#include \"draw.hpp\"\n#include <vector>\n");
    write("app/main.cpp", "#include \"render/draw.hpp\"\n#include <core/base.hpp>\n#include \"../core/base.hpp\"\n");
  }

  /// Writes `text` to root_/path, creating its folders.
  void write(const std::string& path, const std::string& text) const {
    fs::create_directories((root_ / path).parent_path());
    std::ofstream(root_ / path) << text;
  }

  /// Every check's findings on the scratch repository.
  std::string violations() const {
    const std::vector<FolderRule> rules = design_rules(root_);
    return include_violations(root_, rules) + link_violations(root_, rules) + find_cycle(rules) +
           loosened_edges(rules);
  }

  fs::path root_;  ///< the scratch repository
};

TEST_F(LayeringFixture, KeptLayeringHasNoViolation) { EXPECT_EQ(violations(), ""); }

TEST_F(LayeringFixture, BackEdgeThroughDotDotFails) {
  write("render/sub/back.cpp", "#include \"../../app/cli.hpp\"\n");
  EXPECT_EQ(violations(), "render/sub/back.cpp:1 includes app/ (allowed: render, core)\n");
}

TEST_F(LayeringFixture, BackEdgeThroughAngleBracketsFails) {
  write("render/back.hpp", "#pragma once\n#  include <app/cli.hpp>\n");
  EXPECT_EQ(violations(), "render/back.hpp:2 includes app/ (allowed: render, core)\n");
}

TEST_F(LayeringFixture, CycleInTheTableFails) {
  write("docs/DESIGN.md", std::string(kTable) + "| `io/` | files | core, raycast |\n| `raycast/` | rays | io |\n");
  EXPECT_NE(violations().find("io -> raycast -> io"), std::string::npos) << violations();
}

TEST_F(LayeringFixture, LinkLineTheTableForbidsFails) {
  write("CMakeLists.txt", std::string(kCMake) + "target_link_libraries(silva_core INTERFACE\n  silva_render)\n");
  write("render/CMakeLists.txt", "add_library(silva_render_extra STATIC x.cpp)\n"
                                 "target_link_libraries(silva_render_extra PUBLIC silva_app)\n");
  EXPECT_EQ(violations(),
            "CMakeLists.txt: silva_core links silva_render (core/ may include: none of ours)\n"
            "render/CMakeLists.txt: silva_render_extra links silva_app (render/ may include: core)\n");
}

TEST_F(LayeringFixture, LooseningTheTableAloneFails) {
  write("docs/DESIGN.md", "| `core/` | basics | std |\n| `render/` | pixels | core, world |\n| `app/` | CLI | core, render |\n");
  write("render/back.cpp", "#include \"world/terrain.hpp\"\n");
  EXPECT_EQ(violations(),
            "docs/DESIGN.md: render/ may include world/, beyond the pinned layering (at most: render, core)\n");
}

}  // namespace
}  // namespace silva::house
