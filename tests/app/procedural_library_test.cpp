// A library of generator entries (what `silva assets build` writes by default): metadata on load,
// meshes made on first use, identical to generating the variant directly.
#include <gtest/gtest.h>

#include <fstream>
#include <thread>

#include "app/commands/assets/asset_files.hpp"
#include "assets/load_library.hpp"
#include "core/error.hpp"

namespace silva::assets {
namespace {

namespace fs = std::filesystem;

/// A scratch folder holding a generator library of 2 variants per generator (seed 42).
class ProceduralLibraryTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(fs::temp_directory_path() / ("silva_procedural_library_" + std::to_string(::getpid())));
    fs::remove_all(*dir_);
    app::build_library(*dir_, false, 42, 2);
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  /// library.json's text with `from` replaced by `to` (once), written to a new folder.
  static fs::path edited(const std::string& name, const std::string& from, const std::string& to) {
    std::ifstream f(*dir_ / "library.json");
    std::string text(std::istreambuf_iterator<char>(f), {});
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    const fs::path d = *dir_ / name;
    fs::create_directories(d);
    std::ofstream(d / "library.json") << text;
    return d / "library.json";
  }
  static fs::path* dir_;
};
fs::path* ProceduralLibraryTest::dir_ = nullptr;

TEST_F(ProceduralLibraryTest, WritesOnlyTheManifest) {
  size_t files = 0;
  for (const auto& entry : fs::directory_iterator(*dir_)) files += entry.is_regular_file() ? 1 : 0;
  EXPECT_EQ(files, 1u);
}

TEST_F(ProceduralLibraryTest, LoadedVariantsEqualDirectlyGeneratedOnes) {
  const AssetLibrary lib = load_library(*dir_ / "library.json");
  ASSERT_EQ(lib.assets.size(), 2 * factories().size());
  for (const Asset& loaded : lib.assets) {
    SCOPED_TRACE(loaded.name);
    ASSERT_TRUE(loaded.source.has_value());
    const Factory* f = find_factory(loaded.source->generator);
    ASSERT_NE(f, nullptr);
    const Asset direct = make_asset(*f, 42, loaded.source->variant);
    EXPECT_EQ(loaded.name, direct.name);
    EXPECT_EQ(loaded.kind, direct.kind);
    EXPECT_EQ(loaded.role, direct.role);
    EXPECT_EQ(loaded.lod_screen_sizes, direct.lod_screen_sizes);
    EXPECT_EQ(loaded.proxy.shape, direct.proxy.shape);
    EXPECT_NEAR(loaded.proxy.radius, direct.proxy.radius, 1e-6f);
    EXPECT_NEAR((loaded.proxy.center - direct.proxy.center).norm(), 0.0f, 1e-5f);
    ASSERT_EQ(loaded.lods().size(), direct.lods().size());
    for (size_t k = 0; k < direct.lods().size(); ++k) {
      EXPECT_EQ(loaded.lods()[k].positions, direct.lods()[k].positions);
      EXPECT_EQ(loaded.lods()[k].indices, direct.lods()[k].indices);
    }
  }
}

TEST_F(ProceduralLibraryTest, MeshesAreMadeOnceWhateverThreadAsksFirst) {
  const AssetLibrary lib = load_library(*dir_ / "library.json");
  const Asset& a = lib.assets.front();
  const std::vector<Mesh>* seen[4] = {};
  std::vector<std::thread> threads;
  for (auto& s : seen) threads.emplace_back([&a, &s] { s = &a.lods(); });
  for (auto& t : threads) t.join();
  for (const auto* s : seen) EXPECT_EQ(s, seen[0]);
  EXPECT_FALSE(seen[0]->empty());
}

TEST_F(ProceduralLibraryTest, BadGeneratorEntriesAreNamed) {
  const auto expect_error = [](const fs::path& manifest, const std::string& needle) {
    try {
      load_library(manifest);
      ADD_FAILURE() << "no error for " << needle;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  const std::string first = factories()[0].prefix;
  expect_error(edited("unknown", "\"generator\": \"" + first + "\"", "\"generator\": \"oak_of_mordor\""),
               "assets[0].generator 'oak_of_mordor' is not a built-in generator");
  expect_error(edited("seed", "\"seed\": \"0x2a\"", "\"seed\": \"42\""), "assets[0].seed must be a hexadecimal");
  expect_error(edited("variant", "\"variant\": 0", "\"variant\": -1"), "assets[0].variant must be an integer");
  expect_error(edited("both", "\"generator\":", "\"file\": \"x.glb\", \"generator\":"),
               "needs exactly one of \"file\" and \"generator\"");
}

}  // namespace
}  // namespace silva::assets
