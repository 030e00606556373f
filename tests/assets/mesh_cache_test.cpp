#include "assets/mesh_cache.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "assets/factory.hpp"
#include "assets/library.hpp"
#include "assets/lod.hpp"
#include "tests/common/mesh_equal.hpp"
#include "tests/common/scratch_dirs.hpp"

namespace silva::assets {
namespace {

namespace fs = std::filesystem;

/// A fresh, empty folder for one test.
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / "silva_mesh_cache_test" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  test::remove_when_passed(dir);
  return dir;
}

/// Makes a variant's LODs as the library does, counting the calls.
struct CountingMake {
  ProceduralSource source;  ///< The variant.
  int calls = 0;            ///< How often it was made.
  /// The make function for cached_lods.
  std::function<std::vector<Mesh>()> fn() {
    return [this] {
      ++calls;
      return build_lods(generate_variant(*find_factory(source.generator), source.seed, source.variant, Season::Summer).mesh)
          .lods;
    };
  }
};

/// Every regular file under `dir` whose name holds `part` (at its end when `at_end`).
std::vector<fs::path> files_with(const fs::path& dir, const std::string& part, bool at_end = true) {
  std::vector<fs::path> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    const size_t at = name.rfind(part);
    if (e.is_regular_file() && at != std::string::npos && (!at_end || at + part.size() == name.size()))
      out.push_back(e.path());
  }
  return out;
}

TEST(MeshCache, RootFollowsTheEnvironment) {
  EXPECT_EQ(mesh_cache_root("/data/c", "/x", "/home/u"), fs::path("/data/c"));
  EXPECT_EQ(mesh_cache_root("off", "/x", "/home/u"), fs::path());
  EXPECT_EQ(mesh_cache_root(nullptr, "/x", "/home/u"), fs::path("/x/silva/meshes"));
  EXPECT_EQ(mesh_cache_root("", "", "/home/u"), fs::path("/home/u/.cache/silva/meshes"));
  EXPECT_EQ(mesh_cache_root(nullptr, nullptr, nullptr), fs::path());
}

TEST(MeshCache, TheExecutableHasABuildId) {
  const std::string id = executable_build_id();
  EXPECT_GE(id.size(), 16u);
  EXPECT_EQ(id.find_first_not_of("0123456789abcdef"), std::string::npos) << id;
  EXPECT_EQ(executable_build_id(), id);
}

TEST(MeshCache, ASecondUseReadsTheSameMeshesWithoutMakingThem) {
  const fs::path folder = scratch("second_use") / "build-0123abcd";
  for (const char* generator : {"spruce", "birch", "fern"}) {
    CountingMake make{{generator, 2, kDefaultAssetSeed}};
    const std::vector<Mesh> made = cached_lods(folder, make.source, Season::Summer, make.fn());
    const std::vector<Mesh> read = cached_lods(folder, make.source, Season::Summer, make.fn());
    EXPECT_EQ(make.calls, 1) << generator;
    ASSERT_EQ(read.size(), made.size()) << generator;
    for (size_t k = 0; k < made.size(); ++k) test::expect_same_mesh(read[k], made[k], generator);
  }
  EXPECT_EQ(files_with(folder, ".lods").size(), 3u);
  EXPECT_FALSE(files_with(folder / "masks", ".mask").empty());
  EXPECT_TRUE(files_with(folder, ".tmp", false).empty());
  // Another season is another entry.
  CountingMake autumn{{"birch", 2, kDefaultAssetSeed}};
  cached_lods(folder, autumn.source, Season::Autumn, autumn.fn());
  EXPECT_EQ(autumn.calls, 1);
}

TEST(MeshCache, ADamagedOrMissingEntryIsMadeAgainAndRepaired) {
  const fs::path folder = scratch("damaged") / "build-0123abcd";
  CountingMake make{{"beech", 4, kDefaultAssetSeed}};
  const std::vector<Mesh> made = cached_lods(folder, make.source, Season::Summer, make.fn());
  const fs::path entry = files_with(folder, ".lods").at(0);
  const auto size = fs::file_size(entry);
  fs::resize_file(entry, size / 2);
  const std::vector<Mesh> again = cached_lods(folder, make.source, Season::Summer, make.fn());
  EXPECT_EQ(make.calls, 2);
  EXPECT_EQ(fs::file_size(entry), size);
  for (const fs::path& mask : files_with(folder / "masks", ".mask")) fs::remove(mask);
  const std::vector<Mesh> third = cached_lods(folder, make.source, Season::Summer, make.fn());
  EXPECT_EQ(make.calls, 3);  // its masks were gone
  for (size_t k = 0; k < made.size(); ++k) {
    test::expect_same_mesh(again.at(k), made[k], "after repair");
    test::expect_same_mesh(third.at(k), made[k], "after masks removed");
  }
}

TEST(MeshCache, AFolderThatCannotBeWrittenOnlyCostsTheMaking) {
  const fs::path dir = scratch("unwritable");
  std::ofstream(dir / "file") << "not a folder";
  CountingMake make{{"rock", 1, kDefaultAssetSeed}};
  const std::vector<Mesh> a = cached_lods(dir / "file" / "build-0123abcd", make.source, Season::Summer, make.fn());
  const std::vector<Mesh> b = cached_lods(dir / "file" / "build-0123abcd", make.source, Season::Summer, make.fn());
  EXPECT_EQ(make.calls, 2);
  EXPECT_FALSE(a.empty());
  test::expect_same_mesh(b.at(0), a.at(0), "uncached");
  // No cache at all: made every time.
  cached_lods({}, make.source, Season::Summer, make.fn());
  EXPECT_EQ(make.calls, 3);
}

TEST(MeshCache, ANewBuildKeepsThreeOtherBuildsAndNothingElseIsTouched) {
  const fs::path root = scratch("prune");
  const auto now = fs::file_time_type::clock::now();
  for (int k = 0; k < 5; ++k) {
    const fs::path old = root / ("build-aaaa" + std::to_string(k));
    fs::create_directories(old);
    fs::last_write_time(old, now - std::chrono::hours(10 - k));
  }
  fs::create_directories(root / "notes");
  fs::create_directories(root / "build-not-hex");
  fs::last_write_time(root / "notes", now - std::chrono::hours(100));
  CountingMake make{{"rock", 0, kDefaultAssetSeed}};
  cached_lods(root / "build-bbbb", make.source, Season::Summer, make.fn());
  for (int k = 0; k < 5; ++k) EXPECT_EQ(fs::exists(root / ("build-aaaa" + std::to_string(k))), k >= 2) << k;
  EXPECT_TRUE(fs::exists(root / "notes"));
  EXPECT_TRUE(fs::exists(root / "build-not-hex"));
  EXPECT_TRUE(fs::exists(root / "build-bbbb"));
}

}  // namespace
}  // namespace silva::assets
