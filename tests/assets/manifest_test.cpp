#include "assets/manifest.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "assets/factory.hpp"
#include "core/error.hpp"

namespace silva::assets {
namespace {

namespace fs = std::filesystem;

class ManifestTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("silva_manifest_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& text) {
    const fs::path p = dir_ / "library.json";
    std::ofstream(p) << text;
    return p;
  }
  /// Expects read_manifest to throw InputError whose message names the file and `key`.
  void expect_error(const std::string& text, const std::string& key) {
    const fs::path p = write(text);
    try {
      read_manifest(p);
      FAIL() << "no error for " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
  fs::path dir_;
};

const char* kEntry = R"({"name": "r", "file": "r.obj", "kind": "rock", "class": "obstacle",
   "parts": {"stone": "obstacle"},
   "collision": {"shape": "box", "center": [0, 0, 0.2], "half_extents": [0.3, 0.2, 0.2]},
   "lod_screen_sizes": [0.2, 0.05]})";
const std::string kHeader = R"({"format": "silva-asset-library", "version": 1, "assets": [)";
const std::string kGood = kHeader + kEntry + "]}";

std::string with(const std::string& from, const std::string& to) {
  std::string s = kGood;
  s.replace(s.find(from), from.size(), to);
  return s;
}

TEST_F(ManifestTest, RoundTripsEveryGeneratedEntryExactly) {
  std::vector<ManifestEntry> entries;
  for (size_t i = 0; i < factories().size(); ++i) {
    Asset a = make_asset(factories()[i], 9, 0);
    if (i % 2 == 0) a.file = a.name + ".glb";  // even entries: file entries; odd: generator entries
    entries.push_back(manifest_entry(a));
  }
  entries.front().z_up = true;
  std::ofstream(dir_ / "library.json", std::ios::binary) << manifest_text(entries);
  const std::vector<ManifestEntry> back = read_manifest(dir_ / "library.json");
  ASSERT_EQ(back.size(), entries.size());
  for (size_t i = 0; i < back.size(); ++i) {
    const ManifestEntry &a = entries[i], &b = back[i];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.file, b.file);
    EXPECT_EQ(a.kind, b.kind);
    EXPECT_EQ(a.role, b.role);
    EXPECT_EQ(a.z_up, b.z_up);
    EXPECT_EQ(a.parts, b.parts);
    EXPECT_EQ(a.lod_screen_sizes, b.lod_screen_sizes);
    EXPECT_EQ(a.proxy.shape, b.proxy.shape);
    EXPECT_EQ(a.proxy.center, b.proxy.center);
    EXPECT_EQ(a.proxy.radius, b.proxy.radius);
    EXPECT_EQ(a.proxy.height, b.proxy.height);
    EXPECT_EQ(a.proxy.half_extents, b.proxy.half_extents);
    EXPECT_EQ(a.proxy.axis, b.proxy.axis);
    ASSERT_EQ(a.source.has_value(), i % 2 == 1);
    ASSERT_EQ(b.source.has_value(), i % 2 == 1);
    if (a.source) {
      EXPECT_EQ(a.source->generator, b.source->generator);
      EXPECT_EQ(a.source->variant, b.source->variant);
      EXPECT_EQ(a.source->seed, b.source->seed);
    }
  }
  EXPECT_EQ(back[0].parts.at("needles_spruce"), Role::TreeCanopy);
  EXPECT_EQ(back[0].parts.at("bark_spruce"), Role::TreeTrunk);
}

TEST_F(ManifestTest, ReadsAHandWrittenEntry) {
  const auto e = read_manifest(write(kGood));
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].kind, AssetKind::Rock);
  EXPECT_EQ(e[0].proxy.shape, CollisionProxy::Shape::Box);
  EXPECT_FALSE(e[0].z_up);
}

TEST_F(ManifestTest, BadManifestsNameTheFileAndKey) {
  expect_error("{not json", "not valid JSON");
  expect_error(with(R"("format": "silva-asset-library", )", ""), "library.format");
  expect_error(with(R"("version": 1)", R"("version": 7)"), "library.version");
  expect_error(with(R"("name": "r", )", ""), "assets[0].name");
  expect_error(with(R"("kind": "rock")", R"("kind": "boulder")"), "assets[0].kind");
  expect_error(with(R"("class": "obstacle")", R"("class": "stone")"), "assets[0].class");
  expect_error(with(R"({"stone": "obstacle"})", R"({"stone": "pebble"})"), "assets[0].parts.stone");
  expect_error(with(R"("shape": "box")", R"("shape": "cone")"), "assets[0].collision.shape");
  expect_error(with(R"("half_extents": [0.3, 0.2, 0.2])", R"("half_extents": [0.3, 0.2])"),
               "assets[0].collision.half_extents");
  // In-range coordinates but a proxy every neighbour would collide with (planning ran for minutes).
  expect_error(with(R"("half_extents": [0.3, 0.2, 0.2])", R"("half_extents": [999, 0.2, 0.2])"),
               "assets[0].collision.half_extents must be positive and at most 40 m");
  expect_error(with("[0.2, 0.05]", "[0.05, 0.2]"), "assets[0].lod_screen_sizes");
  expect_error(with(R"("file": "r.obj", )", ""), "assets[0] needs exactly one of \"file\" and \"generator\"");
  expect_error(with(R"("parts": {"stone": "obstacle"},)", ""), "assets[0].parts");
  const std::string dup = kHeader + kEntry + "," + kEntry + "]}";
  expect_error(dup, "assets[1].name");
}

TEST_F(ManifestTest, MissingManifestIsInputError) {
  EXPECT_THROW(read_manifest(dir_ / "absent.json"), InputError);
}

}  // namespace
}  // namespace silva::assets
