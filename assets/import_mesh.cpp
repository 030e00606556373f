#include "assets/import_mesh.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <span>
#include <string_view>

#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/core/utils/logger.hpp>
#include <opencv2/imgproc.hpp>

#include "assets/gltf_triangles.hpp"
#include "core/error.hpp"
#include "core/imgcodecs_symbols.hpp"
#include "core/input_limits.hpp"
#include "core/png_check.hpp"
#include "core/shared_library.hpp"

namespace silva::assets {

namespace {

/// cv::imdecode of encoded texture bytes, from imgcodecs opened at the first texture (core/imgcodecs_symbols.hpp).
cv::Mat decode_texture(const cv::Mat& bytes) {
  static auto* const decode = shared_library_function<cv::Mat(const cv::_InputArray&, int)>(kImgcodecsLibrary, kImdecodeSymbol);
  return decode(bytes, cv::IMREAD_UNCHANGED);
}

/// The material surfaces of a role use when the file's material name is not a core material.
Material default_material(Role role) {
  switch (role) {
    case Role::TreeTrunk: return Material::BarkBroadleaf;
    case Role::TreeCanopy: return Material::Leaves;
    case Role::DeadTree: return Material::BarkDead;
    case Role::Stump: return Material::Wood;
    case Role::GroundVegetation: return Material::Grass;
    case Role::Shrub: return Material::ShrubLeaves;
    case Role::Obstacle: return Material::Rock;
    case Role::Trail: return Material::Trail;
    default: return Material::Ground;
  }
}

/// Reads one asset file's scene and turns its materials and meshes into Silva meshes.
class AssetImporter {
 public:
  AssetImporter(const std::filesystem::path& file, const std::map<std::string, Role>& parts, bool z_up,
                const std::string& where)
      : file_(file), parts_(parts), z_up_(z_up), where_(where) {}

  std::vector<Mesh> run() {
    if (!std::filesystem::is_regular_file(file_)) fail("not found");
    check_glb_container();
    scene_ = importer_.ReadFile(file_.string(), aiProcess_ValidateDataStructure);
    if (scene_ == nullptr || scene_->mRootNode == nullptr || (scene_->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
      fail(std::string("cannot be read: ") + importer_.GetErrorString());
    // Checked as the file states them: joining identical vertices would merge a NaN into another one.
    check_file_vertices();
    check_declared_triangles();
    scene_ = importer_.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                           aiProcess_GenSmoothNormals | aiProcess_FlipUVs | aiProcess_SortByPType);
    if (scene_ == nullptr) fail(std::string("cannot be read: ") + importer_.GetErrorString());
    std::vector<const aiNode*> levels;
    for (int k = 0;; ++k) {
      const aiNode* n = scene_->mRootNode->FindNode(("lod" + std::to_string(k)).c_str());
      if (n == nullptr) break;
      levels.push_back(n);
    }
    if (levels.empty()) levels.push_back(scene_->mRootNode);
    std::vector<Mesh> lods;
    for (const aiNode* level : levels) {
      Mesh m;
      add_node(*level, global_transform(*level), m);
      if (m.triangle_count() == 0) fail("level '" + std::string(level->mName.C_Str()) + "' has no triangles");
      lods.push_back(std::move(m));
    }
    return lods;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError("asset file " + file_.string() + " (" + where_ + "): " + what);
  }

  /// Every vertex of the file finite and within limits::kMaxAssetCoordinate of the origin, every
  /// face index within its mesh.
  void check_file_vertices() const {
    const float limit = float(limits::kMaxAssetCoordinate);
    for (unsigned m = 0; m < scene_->mNumMeshes; ++m) {
      const aiMesh& am = *scene_->mMeshes[m];
      const std::string mesh_name = "mesh '" + std::string(am.mName.C_Str()) + "'";
      for (unsigned v = 0; v < am.mNumVertices; ++v) {
        const aiVector3D& p = am.mVertices[v];
        const Vec3f q(p.x, p.y, p.z);
        if (!q.allFinite() || q.cwiseAbs().maxCoeff() > limit)
          fail(mesh_name + " vertex " + std::to_string(v) + " is not a finite position within " +
               std::to_string(int(limit)) + " m of the origin");
      }
      for (unsigned f = 0; f < am.mNumFaces; ++f)
        for (unsigned k = 0; k < am.mFaces[f].mNumIndices; ++k)
          if (am.mFaces[f].mIndices[k] >= am.mNumVertices)
            fail(mesh_name + " face " + std::to_string(f) + " has vertex index " +
                 std::to_string(am.mFaces[f].mIndices[k]) + " (the mesh has " + std::to_string(am.mNumVertices) +
                 " vertices)");
    }
  }

  /// Every triangle a glTF file declares was read: assimp skips a face with an out-of-range vertex index
  /// without an error.
  void check_declared_triangles() const {
    const std::optional<uint64_t> declared = gltf_declared_triangles(file_);
    if (!declared) return;
    uint64_t read = 0;
    for (unsigned m = 0; m < scene_->mNumMeshes; ++m)
      for (unsigned f = 0; f < scene_->mMeshes[m]->mNumFaces; ++f) read += scene_->mMeshes[m]->mFaces[f].mNumIndices == 3;
    if (read < *declared)
      fail("declares " + std::to_string(*declared) + " triangles, " + std::to_string(*declared - read) +
           " of them with a vertex index past the end of its primitive's vertices");
  }

  static aiMatrix4x4 global_transform(const aiNode& node) {
    aiMatrix4x4 m = node.mTransformation;
    for (const aiNode* p = node.mParent; p != nullptr; p = p->mParent) m = p->mTransformation * m;
    return m;
  }

  /// Assimp (Y up) to Silva (Z up): (x, y, z) -> (x, -z, y); identity for Z-up files.
  Vec3f to_silva(const aiVector3D& v) const { return z_up_ ? Vec3f(v.x, v.y, v.z) : Vec3f(v.x, -v.z, v.y); }

  void add_node(const aiNode& node, const aiMatrix4x4& transform, Mesh& out) {
    const aiMatrix3x3 normal_matrix = aiMatrix3x3(transform).Inverse().Transpose();
    for (unsigned i = 0; i < node.mNumMeshes; ++i) add_mesh(*scene_->mMeshes[node.mMeshes[i]], transform, normal_matrix, out);
    for (unsigned c = 0; c < node.mNumChildren; ++c)
      add_node(*node.mChildren[c], transform * node.mChildren[c]->mTransformation, out);
  }

  void add_mesh(const aiMesh& am, const aiMatrix4x4& transform, const aiMatrix3x3& normal_matrix, Mesh& out) {
    if (!(am.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) return;  // points/lines carry no surface
    const aiMaterial& mat = *scene_->mMaterials[am.mMaterialIndex];
    const std::string name = mat.GetName().C_Str();
    const auto role = parts_.find(name);
    if (role == parts_.end()) fail("part with material '" + name + "' has no class in the manifest's parts");
    MeshPart part;
    part.first_index = uint32_t(out.indices.size());
    part.role = role->second;
    if (!parse_material(name.c_str(), part.material)) {
      part.material = default_material(part.role);
      part.base_color = base_color_of(mat);
    }
    part.mask = mask_of(mat);
    int two_sided = part.mask ? 1 : 0;
    mat.Get(AI_MATKEY_TWOSIDED, two_sided);
    part.double_sided = two_sided != 0;

    const uint32_t base = uint32_t(out.positions.size());
    for (unsigned v = 0; v < am.mNumVertices; ++v) {
      const Vec3f p = to_silva(transform * am.mVertices[v]);
      if (!p.allFinite() || p.cwiseAbs().maxCoeff() > float(limits::kMaxAssetCoordinate))
        fail("mesh '" + std::string(am.mName.C_Str()) + "' vertex " + std::to_string(v) +
             " is placed by its node transform outside " + std::to_string(int(limits::kMaxAssetCoordinate)) +
             " m of the origin (or at no finite position)");
      out.positions.push_back(p);
      aiVector3D n = am.mNormals ? normal_matrix * am.mNormals[v] : aiVector3D(0, 0, 1);
      const Vec3f ns = to_silva(n);
      out.normals.push_back(ns.norm() > 0 ? Vec3f(ns.normalized()) : Vec3f::UnitZ());
      out.uvs.push_back(am.mTextureCoords[0] ? Vec2f(am.mTextureCoords[0][v].x, am.mTextureCoords[0][v].y)
                                             : Vec2f::Zero());
    }
    for (unsigned f = 0; f < am.mNumFaces; ++f) {
      const aiFace& face = am.mFaces[f];
      if (face.mNumIndices != 3) continue;
      for (int k = 0; k < 3; ++k) out.indices.push_back(base + face.mIndices[k]);
    }
    part.index_count = uint32_t(out.indices.size()) - part.first_index;
    if (part.index_count > 0) out.parts.push_back(std::move(part));
  }

  /// The colour texture reference of a material (glTF base colour, else diffuse), or "".
  static std::string texture_of(const aiMaterial& mat) {
    aiString path;
    if (mat.GetTexture(aiTextureType_BASE_COLOR, 0, &path) == AI_SUCCESS ||
        mat.GetTexture(aiTextureType_DIFFUSE, 0, &path) == AI_SUCCESS)
      return path.C_Str();
    return "";
  }

  /// The file's own colour of a material (texture times colour factor), or null when it states
  /// neither (assimp's unnamed default material counts as stating nothing).
  std::shared_ptr<const BaseColor> base_color_of(const aiMaterial& mat) {
    const std::string ref = texture_of(mat);
    aiColor4D colour(1, 1, 1, 1);
    const bool has_colour = std::string(mat.GetName().C_Str()) != AI_DEFAULT_MATERIAL_NAME &&
                            (mat.Get(AI_MATKEY_BASE_COLOR, colour) == AI_SUCCESS ||
                             mat.Get(AI_MATKEY_COLOR_DIFFUSE, colour) == AI_SUCCESS);
    if (ref.empty() && !has_colour) return nullptr;
    const std::string key = ref + "|" + std::to_string(colour.r) + "," + std::to_string(colour.g) + "," +
                            std::to_string(colour.b);
    if (auto it = colours_.find(key); it != colours_.end()) return it->second;
    auto out = std::make_shared<BaseColor>();
    out->factor = Vec3f(colour.r, colour.g, colour.b);
    if (!ref.empty()) {
      cv::Mat image = read_texture(ref);
      if (image.depth() != CV_8U) image.convertTo(image, CV_8U, 1.0 / 257.0);
      cv::Mat rgb;
      cv::cvtColor(image, rgb, image.channels() == 1 ? cv::COLOR_GRAY2RGB
                               : image.channels() == 4 ? cv::COLOR_BGRA2RGB
                                                       : cv::COLOR_BGR2RGB);
      out->width = rgb.cols;
      out->height = rgb.rows;
      for (int y = 0; y < rgb.rows; ++y) out->srgb.insert(out->srgb.end(), rgb.ptr<uint8_t>(y), rgb.ptr<uint8_t>(y) + rgb.cols * 3);
    }
    colours_[key] = out;
    return out;
  }

  /// The alpha mask of a material, or null when it is not alpha-tested.
  std::shared_ptr<const AlphaMask> mask_of(const aiMaterial& mat) {
    aiString mode;
    if (mat.Get(AI_MATKEY_GLTF_ALPHAMODE, mode) == AI_SUCCESS && std::string(mode.C_Str()) == "OPAQUE") return nullptr;
    const std::string ref = texture_of(mat);
    if (ref.empty()) return nullptr;
    float cutoff = 0.5f;
    mat.Get(AI_MATKEY_GLTF_ALPHACUTOFF, cutoff);
    const std::string key = ref + "|" + std::to_string(cutoff);
    if (auto it = masks_.find(key); it != masks_.end()) return it->second;
    const cv::Mat image = read_texture(ref);
    std::shared_ptr<AlphaMask> mask;
    if (image.channels() == 4) {
      cv::Mat alpha;
      cv::extractChannel(image, alpha, 3);
      if (alpha.depth() != CV_8U) alpha.convertTo(alpha, CV_8U, 1.0 / 257.0);
      mask = std::make_shared<AlphaMask>();
      mask->width = alpha.cols;
      mask->height = alpha.rows;
      mask->cutoff = cutoff;
      for (int y = 0; y < alpha.rows; ++y) mask->alpha.insert(mask->alpha.end(), alpha.ptr<uint8_t>(y), alpha.ptr<uint8_t>(y) + alpha.cols);
    }
    masks_[key] = mask;
    return mask;
  }

  /// Decodes a texture: embedded ("*N" or by name) or a file relative to the asset.
  cv::Mat read_texture(const std::string& ref) const {
    // OpenCV prints its own warnings on stderr for images it refuses; Silva's error line says it.
    cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
    cv::Mat image;
    if (const aiTexture* t = scene_->GetEmbeddedTexture(ref.c_str())) {
      if (t->mHeight == 0) {
        check_if_png(ref, {reinterpret_cast<const uint8_t*>(t->pcData), t->mWidth});
        const cv::Mat bytes(1, int(t->mWidth), CV_8U, t->pcData);
        image = decode_texture(bytes);
      } else {
        check_texture_size(ref, t->mWidth, t->mHeight);
        image.create(int(t->mHeight), int(t->mWidth), CV_8UC4);  // aiTexel is BGRA
        std::memcpy(image.data, t->pcData, size_t(t->mWidth) * t->mHeight * 4);
      }
    } else {
      const std::filesystem::path path = file_.parent_path() / ref;
      std::error_code ec;
      if (!std::filesystem::is_regular_file(path, ec)) fail("texture '" + ref + "' cannot be decoded: no such file next to the asset");
      std::string bytes = limits::read_input_file(path, "texture");
      check_if_png(ref, {reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()});
      image = decode_texture(cv::Mat(1, int(bytes.size()), CV_8U, bytes.data()));
    }
    if (image.empty()) fail("texture '" + ref + "' cannot be decoded");
    check_texture_size(ref, unsigned(image.cols), unsigned(image.rows));
    return image;
  }

  /// Refuses a texture larger than limits::kMaxTextureSide on a side.
  void check_texture_size(const std::string& ref, unsigned width, unsigned height) const {
    const unsigned side = unsigned(limits::kMaxTextureSide);
    if (width > side || height > side)
      fail("texture '" + ref + "' is " + std::to_string(width) + "x" + std::to_string(height) + " pixels (at most " +
           std::to_string(side) + " per side)");
  }

  /// Refuses a binary glTF whose header or chunk lengths do not fit the file: assimp allocates what
  /// a chunk claims before reading it (4 GB for a 712-byte file found by the glb fuzz harness).
  void check_glb_container() const {
    std::ifstream in(file_, std::ios::binary);
    std::array<char, 12> head{};
    if (!in.read(head.data(), head.size()) || std::string_view(head.data(), 4) != "glTF") return;
    const uint64_t size = std::filesystem::file_size(file_);
    const auto le32 = [](const char* p) {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return v;  // glTF is little-endian, as every machine Silva builds for
    };
    if (le32(&head[4]) != 2) fail("cannot be read: binary glTF version " + std::to_string(le32(&head[4])) + ", not 2");
    if (le32(&head[8]) != size)
      fail("cannot be read: binary glTF header gives " + std::to_string(le32(&head[8])) + " bytes, the file has " +
           std::to_string(size));
    for (uint64_t at = 12; at < size;) {
      std::array<char, 8> chunk{};
      if (size - at < 8 || !in.read(chunk.data(), chunk.size()))
        fail("cannot be read: binary glTF ends inside a chunk header at byte " + std::to_string(at));
      const uint64_t length = le32(&chunk[0]);
      if (length > size - at - 8)
        fail("cannot be read: binary glTF chunk at byte " + std::to_string(at) + " claims " + std::to_string(length) +
             " bytes, " + std::to_string(size - at - 8) + " remain");
      at += 8 + length;
      in.seekg(std::streamoff(at));
    }
  }

  /// Checks a PNG's structure and size (silva::check_png) before decoding allocates it or libpng
  /// prints its own errors; other formats pass.
  void check_if_png(const std::string& ref, std::span<const uint8_t> bytes) const {
    if (!is_png(bytes)) return;
    try {
      check_png(bytes, "texture '" + ref + "'");
    } catch (const InputError& e) {
      fail(e.what());
    }
  }

  const std::filesystem::path& file_;
  const std::map<std::string, Role>& parts_;
  bool z_up_;
  const std::string& where_;
  Assimp::Importer importer_;
  const aiScene* scene_ = nullptr;
  std::map<std::string, std::shared_ptr<const AlphaMask>> masks_;
  std::map<std::string, std::shared_ptr<const BaseColor>> colours_;  ///< By texture and factor: decoded once per file.
};

}  // namespace

std::vector<Mesh> import_asset_lods(const std::filesystem::path& file, const std::map<std::string, Role>& parts,
                                    bool z_up, const std::string& where) {
  return AssetImporter(file, parts, z_up, where).run();
}

}  // namespace silva::assets
