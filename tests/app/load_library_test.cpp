#include "assets/load_library.hpp"

#include <gtest/gtest.h>

#include <cstring>

#include <array>
#include <fstream>
#include <limits>

#include <opencv2/imgcodecs.hpp>

#include "app/commands/assets/asset_files.hpp"
#include "core/error.hpp"
#include "tests/common/mesh_checks.hpp"
#include "textured_library.hpp"

namespace silva::assets {
using app::build_library;
using silva::test::textured_obj_library;
namespace {

namespace fs = std::filesystem;

/// Builds the library once for all tests of this file (it is the slow part).
class LoadLibraryTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(fs::temp_directory_path() / ("silva_library_test_" + std::to_string(::getpid())));
    fs::remove_all(*dir_);
    built_ = new AssetLibrary(build_library(*dir_, true, 42, 2));
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete built_;
    delete dir_;
  }
  /// A copy of the library folder with library.json replaced by `manifest` (or kept if empty).
  static fs::path variant(const std::string& name, const std::string& manifest = "") {
    const fs::path d = *dir_ / name;
    fs::create_directories(d);
    for (const auto& f : fs::directory_iterator(*dir_))
      if (f.is_regular_file()) fs::copy_file(f.path(), d / f.path().filename(), fs::copy_options::overwrite_existing);
    if (!manifest.empty()) std::ofstream(d / "library.json") << manifest;
    return d / "library.json";
  }
  static std::string manifest_text() {
    std::ifstream f(*dir_ / "library.json");
    return std::string(std::istreambuf_iterator<char>(f), {});
  }
  /// Expects load_library to throw InputError mentioning every string in `needles`.
  static void expect_error(const fs::path& manifest, std::initializer_list<std::string> needles) {
    try {
      load_library(manifest);
      FAIL() << "no error";
    } catch (const InputError& e) {
      for (const std::string& n : needles) EXPECT_NE(std::string(e.what()).find(n), std::string::npos) << e.what();
    }
  }
  static fs::path* dir_;
  static AssetLibrary* built_;
};
fs::path* LoadLibraryTest::dir_ = nullptr;
AssetLibrary* LoadLibraryTest::built_ = nullptr;

TEST_F(LoadLibraryTest, WritesOneGlbPerAssetAndAManifest) {
  EXPECT_TRUE(fs::is_regular_file(*dir_ / "library.json"));
  for (const Asset& a : built_->assets) EXPECT_TRUE(fs::is_regular_file(*dir_ / a.file)) << a.file;
}

TEST_F(LoadLibraryTest, RoundTripThroughAssimpKeepsLodsRolesMasksAndProxies) {
  const AssetLibrary loaded = load_library(*dir_ / "library.json");
  ASSERT_EQ(loaded.assets.size(), built_->assets.size());
  for (size_t i = 0; i < loaded.assets.size(); ++i) {
    const Asset &a = built_->assets[i], &b = loaded.assets[i];
    SCOPED_TRACE(a.name);
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.kind, b.kind);
    EXPECT_EQ(a.role, b.role);
    EXPECT_EQ(a.lod_screen_sizes, b.lod_screen_sizes);
    EXPECT_EQ(a.proxy.shape, b.proxy.shape);
    EXPECT_EQ(a.proxy.center, b.proxy.center);
    EXPECT_EQ(a.proxy.radius, b.proxy.radius);
    EXPECT_EQ(a.proxy.height, b.proxy.height);
    EXPECT_EQ(a.proxy.half_extents, b.proxy.half_extents);
    ASSERT_EQ(a.lods().size(), b.lods().size());
    for (size_t k = 0; k < a.lods().size(); ++k) {
      const Mesh &ma = a.lods()[k], &mb = b.lods()[k];
      test::expect_valid_mesh(mb, "loaded lod" + std::to_string(k));
      EXPECT_EQ(ma.triangle_count(), mb.triangle_count());
      ASSERT_EQ(ma.parts.size(), mb.parts.size());
      for (size_t p = 0; p < ma.parts.size(); ++p) {
        EXPECT_EQ(ma.parts[p].role, mb.parts[p].role);
        EXPECT_EQ(ma.parts[p].material, mb.parts[p].material);
        EXPECT_EQ(ma.parts[p].index_count, mb.parts[p].index_count);
        EXPECT_EQ(ma.parts[p].double_sided, mb.parts[p].double_sided);
        ASSERT_EQ(bool(ma.parts[p].mask), bool(mb.parts[p].mask));
        if (ma.parts[p].mask) {
          EXPECT_EQ(ma.parts[p].mask->alpha, mb.parts[p].mask->alpha);
          EXPECT_EQ(ma.parts[p].mask->width, mb.parts[p].mask->width);
          EXPECT_EQ(ma.parts[p].mask->cutoff, mb.parts[p].mask->cutoff);
        }
      }
      // Geometry comes back in Silva's Z-up axes: same bounds, same corners of each triangle.
      EXPECT_EQ(ma.bounds().min, mb.bounds().min);
      EXPECT_EQ(ma.bounds().max, mb.bounds().max);
      for (size_t t = 0; t < ma.indices.size(); t += 97) {
        EXPECT_EQ(ma.positions[ma.indices[t]], mb.positions[mb.indices[t]]);
        EXPECT_NEAR((ma.normals[ma.indices[t]] - mb.normals[mb.indices[t]]).norm(), 0.0f, 1e-5f);
        EXPECT_NEAR((ma.uvs[ma.indices[t]] - mb.uvs[mb.indices[t]]).norm(), 0.0f, 1e-6f);
      }
    }
  }
  for (size_t k = 0; k < size_t(AssetKind::Count); ++k) EXPECT_EQ(loaded.by_kind[k], built_->by_kind[k]);
}

TEST_F(LoadLibraryTest, BuildIsDeterministic) {
  const fs::path again = *dir_ / "again";
  build_library(again, true, 42, 2);
  for (const Asset& a : built_->assets) {
    std::ifstream x(*dir_ / a.file, std::ios::binary), y(again / a.file, std::ios::binary);
    EXPECT_TRUE(std::equal(std::istreambuf_iterator<char>(x), {}, std::istreambuf_iterator<char>(y))) << a.file;
  }
}

TEST_F(LoadLibraryTest, MissingAssetFileNamesTheFile) {
  const fs::path m = variant("missing");
  fs::remove(m.parent_path() / "rock_01.glb");
  expect_error(m, {"rock_01.glb", "not found"});
}

TEST_F(LoadLibraryTest, CorruptAssetFileNamesTheFile) {
  const fs::path m = variant("corrupt");
  std::ofstream(m.parent_path() / "log_01.glb", std::ios::trunc) << "glTF this is not a model";
  expect_error(m, {"log_01.glb", "cannot be read"});
}

TEST_F(LoadLibraryTest, UntaggedPartNamesTheFileAndMaterial) {
  std::string text = manifest_text();
  const std::string tag = R"("needles_spruce": "tree_canopy")";
  const size_t at = text.find(tag);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, tag.size(), R"("pine_needles": "tree_canopy")");
  expect_error(variant("untagged", text), {"spruce_00.glb", "needles_spruce", "no class"});
}

TEST_F(LoadLibraryTest, BadManifestNamesTheManifest) {
  const fs::path m = variant("badjson", "{\"format\": ");
  expect_error(m, {m.string(), "not valid JSON"});
}

TEST_F(LoadLibraryTest, UserObjAssetGetsLodsBuiltAndYUpTurnedToZUp) {
  const fs::path d = *dir_ / "user";
  fs::create_directories(d);
  // A 2 m tall, Y-up triangulated box-ish pyramid as OBJ (4-sided, apex up along +Y).
  std::ofstream(d / "spire.obj") << "mtllib spire.mtl\nv -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nv 0 2 0\n"
                                    "usemtl granite\nf 1 2 3\nf 1 3 4\nf 1 5 2\nf 2 5 3\nf 3 5 4\nf 4 5 1\n";
  std::ofstream(d / "spire.mtl") << "newmtl granite\nKd 0.5 0.5 0.5\n";
  std::ofstream(d / "library.json") << R"({"format": "silva-asset-library", "version": 1, "assets": [
    {"name": "spire", "file": "spire.obj", "kind": "rock", "class": "obstacle", "parts": {"granite": "obstacle"},
     "collision": {"shape": "sphere", "center": [0, 0, 1], "radius": 1}, "lod_screen_sizes": [0.1]}]})";
  const AssetLibrary lib = load_library(d / "library.json");
  ASSERT_EQ(lib.assets.size(), 1u);
  const Asset& a = lib.assets[0];
  ASSERT_GE(a.lods().size(), 1u);
  EXPECT_EQ(a.lods()[0].triangle_count(), 6u);
  EXPECT_EQ(a.lods()[0].parts[0].role, Role::Obstacle);
  EXPECT_EQ(a.lods()[0].parts[0].material, Material::Rock);  // "granite" is no core material
  EXPECT_FLOAT_EQ(a.lods()[0].bounds().max.z(), 2.0f);      // +Y became +Z
  EXPECT_EQ(a.lod_screen_sizes.size(), a.lods().size() - 1);
  EXPECT_EQ(lib.by_kind[size_t(AssetKind::Rock)], std::vector<uint32_t>{0});
}

TEST_F(LoadLibraryTest, UserAssetKeepsItsOwnTextureAndColour) {
  const fs::path d = *dir_ / "textured";
  fs::create_directories(d);
  cv::Mat texture(1, 2, CV_8UC3);
  texture.at<cv::Vec3b>(0, 0) = cv::Vec3b(0, 0, 255);  // OpenCV is BGR: red
  texture.at<cv::Vec3b>(0, 1) = cv::Vec3b(255, 0, 0);  // blue
  ASSERT_TRUE(cv::imwrite((d / "bark.png").string(), texture));
  std::ofstream(d / "post.obj") << "mtllib post.mtl\nv 0 0 0\nv 1 0 0\nv 1 2 0\nv 0 2 0\n"
                                   "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                   "usemtl photo_bark\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n"
                                   "usemtl painted\nf 1/1 3/3 2/2\n";
  std::ofstream(d / "post.mtl") << "newmtl photo_bark\nKd 0.8 0.7 0.6\nmap_Kd bark.png\n"
                                   "newmtl painted\nKd 0.1 0.2 0.3\n";
  std::ofstream(d / "library.json") << R"({"format": "silva-asset-library", "version": 1, "assets": [
    {"name": "post", "file": "post.obj", "kind": "stump", "class": "stump",
     "parts": {"photo_bark": "stump", "painted": "stump"},
     "collision": {"shape": "sphere", "center": [0, 0, 1], "radius": 1}, "lod_screen_sizes": []}]})";
  const AssetLibrary lib = load_library(d / "library.json");
  ASSERT_EQ(lib.assets.size(), 1u);
  const Mesh& m = lib.assets[0].lods()[0];
  ASSERT_EQ(m.parts.size(), 2u);
  const BaseColor* bark = m.parts[0].base_color.get();
  const BaseColor* painted = m.parts[1].base_color.get();
  ASSERT_NE(bark, nullptr);
  ASSERT_NE(painted, nullptr);
  EXPECT_EQ(bark->width, 2);
  EXPECT_EQ(bark->height, 1);
  EXPECT_EQ(bark->srgb, (std::vector<uint8_t>{255, 0, 0, 0, 0, 255}));  // RGB order
  EXPECT_TRUE(bark->factor.isApprox(Vec3f(0.8f, 0.7f, 0.6f)));
  EXPECT_EQ(painted->width, 0);  // colour only
  EXPECT_TRUE(painted->factor.isApprox(Vec3f(0.1f, 0.2f, 0.3f)));
  EXPECT_EQ(m.parts[0].material, Material::Wood);  // the role's material still decides translucency
}

TEST_F(LoadLibraryTest, CoreMaterialNamesKeepTheProceduralLook) {
  const AssetLibrary loaded = load_library(*dir_ / "library.json");  // our glb files name core materials
  for (const Asset& a : loaded.assets)
    for (const Mesh& lod : a.lods())
      for (const MeshPart& p : lod.parts) EXPECT_EQ(p.base_color, nullptr) << a.name;
}

/// A one-asset library of `obj` (material "granite") with `collision`, in folder `name`.
fs::path user_obj_library(const fs::path& root, const std::string& name, const std::string& obj,
                          const std::string& collision = R"({"shape": "sphere", "center": [0, 0, 1], "radius": 1})") {
  const fs::path d = root / name;
  fs::create_directories(d);
  std::ofstream(d / "a.obj") << "mtllib a.mtl\n" << obj;
  std::ofstream(d / "a.mtl") << "newmtl granite\nKd 0.5 0.5 0.5\n";
  std::ofstream(d / "library.json") << R"({"format": "silva-asset-library", "version": 1, "assets": [
    {"name": "a", "file": "a.obj", "kind": "rock", "class": "obstacle", "parts": {"granite": "obstacle"},
     "collision": )" + collision + R"(, "lod_screen_sizes": []}]})";
  return d / "library.json";
}

/// A binary glTF of JSON chunk `json` (padded with spaces) and binary chunk `bin`.
std::string glb_container(const std::string& json, const std::string& bin) {
  const std::string chunk = json + std::string((4 - json.size() % 4) % 4, ' ');
  auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  return u32(0x46546C67) + u32(2) + u32(uint32_t(12 + 8 + chunk.size() + 8 + bin.size())) + u32(uint32_t(chunk.size())) +
         u32(0x4E4F534A) + chunk + u32(uint32_t(bin.size())) + u32(0x004E4942) + bin;
}

/// A binary glTF of one triangle with the given corner positions and material "granite".
std::string triangle_glb(const std::array<float, 9>& corners) {
  const std::string json =
      R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
      R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],"materials":[{"name":"granite"}],)"
      R"("buffers":[{"byteLength":36}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
      R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}]})";
  return glb_container(json, std::string(reinterpret_cast<const char*>(corners.data()), 36));
}

TEST_F(LoadLibraryTest, CorruptUserAssetsNameFileAndField) {
  const std::string tri = "usemtl granite\nf 1 2 3\n";
  const fs::path nan_dir = *dir_ / "nan";
  fs::create_directories(nan_dir);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::ofstream(nan_dir / "a.glb", std::ios::binary) << triangle_glb({0, 0, 0, 1, 0, 0, nan, 1, 0});
  std::ofstream(nan_dir / "library.json") << R"({"format": "silva-asset-library", "version": 1, "assets": [
    {"name": "a", "file": "a.glb", "kind": "rock", "class": "obstacle", "parts": {"granite": "obstacle"},
     "collision": {"shape": "sphere", "center": [0, 0, 1], "radius": 1}, "lod_screen_sizes": []}]})";
  expect_error(nan_dir / "library.json", {"a.glb", "vertex 2", "finite"});
  expect_error(user_obj_library(*dir_, "far", "v 0 0 0\nv 1 0 0\nv 1e30 1 0\n" + tri), {"a.obj", "vertex 2"});
  expect_error(user_obj_library(*dir_, "box", "v 0 0 0\nv 1 0 0\nv 0 1 0\n" + tri,
                                R"({"shape": "box", "center": [0, 0, 0], "half_extents": [1e300, 1, 1]})"),
               {"library.json", "collision.half_extents"});
}

TEST_F(LoadLibraryTest, BinaryGltfChunkLongerThanTheFileIsRefusedBeforeAssimp) {
  // The glb fuzz harness's finding: a JSON chunk claiming 4 GB made assimp allocate it (out of memory).
  const fs::path d = *dir_ / "long_chunk";
  fs::create_directories(d);
  std::string glb = triangle_glb({0, 0, 0, 1, 0, 0, 0, 1, 0});
  const uint32_t claim = 0xffff0280u;
  std::memcpy(&glb[12], &claim, 4);
  std::ofstream(d / "a.glb", std::ios::binary) << glb;
  std::ofstream(d / "library.json") << R"({"format": "silva-asset-library", "version": 1, "assets": [
    {"name": "a", "file": "a.glb", "kind": "rock", "class": "obstacle", "parts": {"granite": "obstacle"},
     "collision": {"shape": "sphere", "center": [0, 0, 1], "radius": 1}, "lod_screen_sizes": []}]})";
  expect_error(d / "library.json", {"a.glb", "chunk at byte 12 claims 4294902400 bytes"});
  std::memcpy(&glb[8], &claim, 4);  // the header's total length wrong as well: that is named first
  std::ofstream(d / "a.glb", std::ios::binary | std::ios::trunc) << glb;
  expect_error(d / "library.json", {"a.glb", "header gives 4294902400 bytes"});
}

TEST_F(LoadLibraryTest, GltfFaceIndexPastTheVerticesIsRefusedNotDropped) {
  // Two indexed triangles over three vertices, the second's last index 4e9: assimp drops that face silently.
  const std::string json =
      R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
      R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0}]}],)"
      R"("materials":[{"name":"granite"}],"buffers":[{"byteLength":60}],)"
      R"("bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":24}],)"
      R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},)"
      R"({"bufferView":1,"componentType":5125,"count":6,"type":"SCALAR"}]})";
  const std::array<float, 9> corners = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const auto glb = [&](uint32_t last_index) {
    const std::array<uint32_t, 6> indices = {0, 1, 2, 0, 1, last_index};
    return glb_container(json, std::string(reinterpret_cast<const char*>(corners.data()), 36) +
                                   std::string(reinterpret_cast<const char*>(indices.data()), 24));
  };
  const fs::path d = *dir_ / "far_index";
  fs::create_directories(d);
  std::ofstream(d / "library.json") << R"({"format": "silva-asset-library", "version": 1, "assets": [
    {"name": "a", "file": "a.glb", "kind": "rock", "class": "obstacle", "parts": {"granite": "obstacle"},
     "collision": {"shape": "sphere", "center": [0, 0, 1], "radius": 1}, "lod_screen_sizes": []}]})";
  std::ofstream(d / "a.glb", std::ios::binary) << glb(4000000000u);
  expect_error(d / "library.json", {"a.glb", "declares 2 triangles, 1 of them with a vertex index past the end"});
  std::ofstream(d / "a.glb", std::ios::binary | std::ios::trunc) << glb(2);
  EXPECT_NO_THROW(load_library(d / "library.json"));
}

TEST_F(LoadLibraryTest, HugeTextureIsRefusedBeforeDecoding) {
  const fs::path d = *dir_ / "huge_texture";
  textured_obj_library(d, "big.png");
  // A PNG header claiming 60000 x 60000 pixels: refused from the header, never allocated.
  const unsigned char header[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R',
                                  0, 0, 0xea, 0x60, 0, 0, 0xea, 0x60, 8, 6, 0, 0, 0};
  std::ofstream(d / "big.png", std::ios::binary).write(reinterpret_cast<const char*>(header), sizeof header);
  expect_error(d / "library.json", {"a.obj", "big.png", "60000x60000"});
}

TEST_F(LoadLibraryTest, ManifestThatIsAFolderOrTooDeep) {
  const fs::path folder = *dir_ / "folder";
  fs::create_directories(folder / "library.json");
  expect_error(folder / "library.json", {"library.json", "not a regular file"});
  const fs::path deep = variant("deep", std::string(100000, '[') + std::string(100000, ']'));
  expect_error(deep, {deep.string(), "nested deeper than 64"});
}

}  // namespace
}  // namespace silva::assets
