// Known answers for the folder an #include line reaches, from the including file's place.
#include <gtest/gtest.h>

#include "include_lines.hpp"

namespace silva::house {
namespace {

TEST(IncludeLines, QuotedFolderPathsAreFromTheRoot) {
  EXPECT_EQ(included_source_folder("app/main.cpp", "#include \"render/gbuffer.hpp\""), "render");
  EXPECT_EQ(included_source_folder("app/main.cpp", "  #  include \"ecs/world.hpp\"  // why"), "ecs");
  EXPECT_EQ(included_source_folder("app/cli/cli.cpp", "#include \"pipeline/config/load.hpp\""), "pipeline");
  EXPECT_EQ(included_source_folder("render/a.cpp", "#include \"tests/common/scratch_dirs.hpp\""), "");
  EXPECT_EQ(included_source_folder("render/a.cpp", "int x;  // #include \"app/x.hpp\""), "");
}

TEST(IncludeLines, AngleBracketsReachOurFoldersToo) {
  EXPECT_EQ(included_source_folder("render/a.cpp", "#include <world/terrain.hpp>"), "world");
  EXPECT_EQ(included_source_folder("render/a.cpp", "#include <vector>"), "");
  EXPECT_EQ(included_source_folder("render/a.cpp", "#include <hwy/highway.h>"), "");
  EXPECT_EQ(included_source_folder("render/a.cpp", "#include <../app/x.hpp>"), "");
}

TEST(IncludeLines, RelativePathsAreFromTheIncludingFile) {
  EXPECT_EQ(included_source_folder("render/a.cpp", "#include \"../world/terrain.hpp\""), "world");
  EXPECT_EQ(included_source_folder("app/commands/bench/b.cpp", "#include \"../../../bench/harness/h.hpp\""), "bench");
  EXPECT_EQ(included_source_folder("render/sub/a.cpp", "#include \"../../x.hpp\""), "");
  EXPECT_EQ(included_source_folder("render/a.cpp", "#include \"../../x.hpp\""), "");
  EXPECT_EQ(included_source_folder("render/a.cpp", "#include \"./local.hpp\""), "render");
  EXPECT_EQ(included_source_folder("render/a.cpp", "#include \"local.hpp\""), "render");
  EXPECT_EQ(included_source_folder("render/a.cpp", "#include \"sub/x.hpp\""), "render");
  EXPECT_EQ(included_source_folder("render/a.cpp", "#include \"core/../app/x.hpp\""), "app");
}

}  // namespace
}  // namespace silva::house
