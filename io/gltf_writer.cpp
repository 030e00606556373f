#include "io/gltf_writer.hpp"

#include <array>
#include <cstring>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/image_codecs.hpp"

namespace silva::io {

namespace {

using nlohmann::json;

static_assert(sizeof(Vec3f) == 3 * sizeof(float) && sizeof(Vec2f) == 2 * sizeof(float),
              "vertex attributes are written as packed float arrays");

constexpr int kFloat = 5126, kUint32 = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr int kNearest = 9728, kRepeat = 10497;

/// Linear base colours per core material, so viewers show plausible colours.
constexpr std::array<std::array<float, 3>, size_t(Material::Count)> kBaseColor = {{
    {0.25f, 0.18f, 0.10f}, {0.45f, 0.40f, 0.30f}, {0.25f, 0.17f, 0.11f}, {0.35f, 0.30f, 0.25f},
    {0.50f, 0.48f, 0.45f}, {0.08f, 0.20f, 0.07f}, {0.15f, 0.35f, 0.08f}, {0.25f, 0.45f, 0.10f},
    {0.15f, 0.40f, 0.10f}, {0.18f, 0.32f, 0.10f}, {0.40f, 0.40f, 0.38f}, {0.45f, 0.32f, 0.20f},
    {0.30f, 0.26f, 0.20f}, {0.55f, 0.45f, 0.32f}, {0.15f, 0.30f, 0.06f}, {0.35f, 0.22f, 0.10f},
    {0.30f, 0.17f, 0.11f}, {0.55f, 0.28f, 0.12f}, {0.35f, 0.18f, 0.12f}, {0.50f, 0.50f, 0.46f},
    {0.75f, 0.74f, 0.70f}, {0.28f, 0.25f, 0.21f}, {0.06f, 0.15f, 0.07f}, {0.12f, 0.20f, 0.10f},
    {0.22f, 0.40f, 0.10f}, {0.16f, 0.36f, 0.07f}, {0.26f, 0.44f, 0.09f}, {0.12f, 0.28f, 0.06f},
    {0.55f, 0.30f, 0.05f}, {0.55f, 0.42f, 0.08f}, {0.22f, 0.19f, 0.16f}, {0.42f, 0.36f, 0.15f},
    {0.50f, 0.46f, 0.34f}, {0.30f, 0.24f, 0.18f}, {0.12f, 0.09f, 0.06f}, {0.20f, 0.45f, 0.10f},
    {0.28f, 0.50f, 0.09f}, {0.85f, 0.84f, 0.80f}, {0.32f, 0.17f, 0.09f},
}};

/// The binary chunk with its bufferViews and accessors.
class BinBuilder {
 public:
  /// Appends raw bytes as a new 4-byte-aligned bufferView; target 0 = none.
  int add_view(const void* data, size_t bytes, int target) {
    bin_.resize((bin_.size() + 3) & ~size_t(3), 0);
    json v = {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", bytes}};
    if (target != 0) v["target"] = target;
    const auto* p = static_cast<const uint8_t*>(data);
    bin_.insert(bin_.end(), p, p + bytes);
    views_.push_back(std::move(v));
    return int(views_.size() - 1);
  }
  /// Adds an accessor over a whole bufferView; returns its index.
  int add_accessor(int view, int component_type, size_t count, const char* type, json min = nullptr,
                   json max = nullptr) {
    json a = {{"bufferView", view}, {"componentType", component_type}, {"count", count}, {"type", type}};
    if (!min.is_null()) a["min"] = std::move(min);
    if (!max.is_null()) a["max"] = std::move(max);
    accessors_.push_back(std::move(a));
    return int(accessors_.size() - 1);
  }
  /// Adds a float accessor of `comps` components per element (VEC2/VEC3/VEC4/SCALAR).
  int add_floats(const float* data, size_t count, int comps, int target, bool with_bounds = false) {
    static constexpr const char* kTypes[] = {"", "SCALAR", "VEC2", "VEC3", "VEC4"};
    const int view = add_view(data, count * size_t(comps) * sizeof(float), target);
    json mn = nullptr, mx = nullptr;
    if (with_bounds) {
      mn = json::array();
      mx = json::array();
      for (int c = 0; c < comps; ++c) {
        float lo = data[c], hi = data[c];
        for (size_t i = 1; i < count; ++i) {
          lo = std::min(lo, data[i * size_t(comps) + size_t(c)]);
          hi = std::max(hi, data[i * size_t(comps) + size_t(c)]);
        }
        mn.push_back(double(lo));
        mx.push_back(double(hi));
      }
    }
    return add_accessor(view, kFloat, count, kTypes[comps], std::move(mn), std::move(mx));
  }
  std::vector<uint8_t>& bin() { return bin_; }
  json& views() { return views_; }
  json& accessors() { return accessors_; }

 private:
  std::vector<uint8_t> bin_;
  json views_ = json::array();
  json accessors_ = json::array();
};

/// Identity of a glTF material: core material, mask and sidedness.
struct MaterialKey {
  Material material;
  const AlphaMask* mask;
  bool double_sided;
  bool operator==(const MaterialKey&) const = default;
};

/// Materials, textures and images in first-use order.
class MaterialTable {
 public:
  explicit MaterialTable(BinBuilder& bin) : bin_(bin) {}
  /// Index of the material for a part, created on first use.
  int index(const MeshPart& part) {
    const MaterialKey key{part.material, part.mask.get(), part.double_sided};
    for (size_t i = 0; i < keys_.size(); ++i)
      if (keys_[i] == key) return int(i);
    const auto& c = kBaseColor[size_t(part.material)];
    json pbr = {{"baseColorFactor", {c[0], c[1], c[2], 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 1.0}};
    json m = {{"name", material_name(part.material)}};
    if (part.mask) {
      pbr["baseColorTexture"] = {{"index", texture(*part.mask)}};
      m["alphaMode"] = "MASK";
      m["alphaCutoff"] = double(part.mask->cutoff);
      // Leaf or needle length in texture units: times the card's metres per texture unit, its length in metres.
      if (part.mask->feature_length > 0.0f) m["extras"] = {{"leaf_length_uv", double(part.mask->feature_length)}};
    }
    m["pbrMetallicRoughness"] = std::move(pbr);
    if (part.double_sided) m["doubleSided"] = true;
    keys_.push_back(key);
    materials_.push_back(std::move(m));
    return int(keys_.size() - 1);
  }
  /// Writes materials/textures/images/samplers into the glTF root.
  void emit(json& root) const {
    if (!materials_.empty()) root["materials"] = materials_;
    if (textures_.empty()) return;
    root["textures"] = textures_;
    root["images"] = images_;
    root["samplers"] = json::array(
        {{{"magFilter", kNearest}, {"minFilter", kNearest}, {"wrapS", kRepeat}, {"wrapT", kRepeat}}});
  }

 private:
  int texture(const AlphaMask& mask) {
    for (size_t i = 0; i < masks_.size(); ++i)
      if (masks_[i] == &mask) return int(i);
    if (mask.width <= 0 || mask.height <= 0 || mask.alpha.size() != size_t(mask.width) * size_t(mask.height))
      throw InputError("glTF export: alpha mask has inconsistent size " + std::to_string(mask.width) + "x" +
                       std::to_string(mask.height));
    cv::Mat rgba(mask.height, mask.width, CV_8UC4, cv::Scalar(255, 255, 255, 255));
    for (int y = 0; y < mask.height; ++y)
      for (int x = 0; x < mask.width; ++x)
        rgba.at<cv::Vec4b>(y, x)[3] = mask.alpha[size_t(y) * size_t(mask.width) + size_t(x)];
    std::vector<uint8_t> png;
    encode_image(".png", rgba, png, {cv::IMWRITE_PNG_COMPRESSION, 6});
    const int view = bin_.add_view(png.data(), png.size(), 0);
    masks_.push_back(&mask);
    images_.push_back({{"bufferView", view}, {"mimeType", "image/png"}});
    textures_.push_back({{"sampler", 0}, {"source", int(images_.size() - 1)}});
    return int(masks_.size() - 1);
  }

  BinBuilder& bin_;
  std::vector<MaterialKey> keys_;
  std::vector<const AlphaMask*> masks_;
  json materials_ = json::array(), textures_ = json::array(), images_ = json::array();
};

/// Serialises one mesh: shared vertex attributes, one index accessor + primitive per part.
json encode_mesh(const GltfMesh& gm, size_t mesh_index, BinBuilder& bin, MaterialTable& materials) {
  const std::string where = "glTF export: mesh " + std::to_string(mesh_index) + " '" + gm.name + "'";
  if (gm.mesh == nullptr) throw InputError(where + " has no geometry");
  const Mesh& m = *gm.mesh;
  const size_t nv = m.positions.size();
  if (nv == 0 || m.normals.size() != nv) throw InputError(where + " needs positions and one normal per vertex");
  if (!gm.part_extras.empty() && gm.part_extras.size() != m.parts.size())
    throw InputError(where + ": part_extras must be empty or one per part");
  json attrs = {{"POSITION", bin.add_floats(m.positions[0].data(), nv, 3, kArrayBuffer, true)},
                {"NORMAL", bin.add_floats(m.normals[0].data(), nv, 3, kArrayBuffer)}};
  if (m.uvs.size() == nv) attrs["TEXCOORD_0"] = bin.add_floats(m.uvs[0].data(), nv, 2, kArrayBuffer);
  json prims = json::array();
  for (size_t p = 0; p < m.parts.size(); ++p) {
    const MeshPart& part = m.parts[p];
    if (part.index_count == 0) continue;
    if (size_t(part.first_index) + part.index_count > m.indices.size() || part.index_count % 3 != 0)
      throw InputError(where + ": part " + std::to_string(p) + " lies outside the index buffer");
    const uint32_t* idx = m.indices.data() + part.first_index;
    for (uint32_t k = 0; k < part.index_count; ++k)
      if (idx[k] >= nv) throw InputError(where + ": index out of range in part " + std::to_string(p));
    const int view = bin.add_view(idx, part.index_count * sizeof(uint32_t), kElementArrayBuffer);
    json prim = {{"attributes", attrs},
                 {"indices", bin.add_accessor(view, kUint32, part.index_count, "SCALAR")},
                 {"material", materials.index(part)},
                 {"mode", 4}};
    if (!gm.part_extras.empty() && !gm.part_extras[p].is_null()) prim["extras"] = gm.part_extras[p];
    prims.push_back(std::move(prim));
  }
  if (prims.empty()) throw InputError(where + " has no triangles");
  return {{"name", gm.name}, {"primitives", std::move(prims)}};
}

/// EXT_mesh_gpu_instancing attributes for a node's copies.
json encode_instances(const std::vector<GltfInstance>& instances, BinBuilder& bin) {
  const size_t n = instances.size();
  std::vector<float> t(3 * n), r(4 * n), s(3 * n), cls(n), hi(n), lo(n);
  for (size_t i = 0; i < n; ++i) {
    const Affine3f& a = instances[i].transform;
    const Mat3f m = a.leftCols<3>();
    const float scale = m.col(0).norm();
    Eigen::Quaternionf q(Mat3f(m / scale));
    q.normalize();
    for (int k = 0; k < 3; ++k) {
      t[3 * i + size_t(k)] = a(k, 3);
      s[3 * i + size_t(k)] = scale;
    }
    r[4 * i + 0] = q.x(), r[4 * i + 1] = q.y(), r[4 * i + 2] = q.z(), r[4 * i + 3] = q.w();
    cls[i] = float(instances[i].class_id & 0xffffu);
    hi[i] = float(instances[i].instance_id >> 16);
    lo[i] = float(instances[i].instance_id & 0xffffu);
  }
  return {{"attributes",
           {{"TRANSLATION", bin.add_floats(t.data(), n, 3, 0)},
            {"ROTATION", bin.add_floats(r.data(), n, 4, 0)},
            {"SCALE", bin.add_floats(s.data(), n, 3, 0)},
            {"_CLASS_ID", bin.add_floats(cls.data(), n, 1, 0)},
            {"_INSTANCE_ID_HI", bin.add_floats(hi.data(), n, 1, 0)},
            {"_INSTANCE_ID_LO", bin.add_floats(lo.data(), n, 1, 0)}}}};
}

/// Serialises one node (matrix, mesh, children, extras, instancing).
json encode_node(const GltfNode& node, size_t index, const GltfDocument& doc, BinBuilder& bin, bool& instancing) {
  const std::string where = "glTF export: node " + std::to_string(index) + " '" + node.name + "'";
  json n = {{"name", node.name}};
  if (node.matrix != Mat4d::Identity())
    n["matrix"] = std::vector<double>(node.matrix.data(), node.matrix.data() + 16);
  if (node.mesh >= 0) {
    if (size_t(node.mesh) >= doc.meshes.size()) throw InputError(where + " refers to a missing mesh");
    n["mesh"] = node.mesh;
  }
  if (!node.children.empty()) {
    for (uint32_t c : node.children)
      if (c >= doc.nodes.size() || c == index) throw InputError(where + " has a bad child index");
    n["children"] = node.children;
  }
  if (!node.extras.is_null()) n["extras"] = node.extras;
  if (!node.instances.empty()) {
    if (node.mesh < 0) throw InputError(where + " has instances but no mesh");
    n["extensions"] = {{"EXT_mesh_gpu_instancing", encode_instances(node.instances, bin)}};
    instancing = true;
  }
  return n;
}

/// Little-endian append of a 32-bit word.
void put_u32(std::vector<uint8_t>& out, uint32_t v) {
  for (int k = 0; k < 4; ++k) out.push_back(uint8_t(v >> (8 * k)));
}

/// Frames JSON text and binary data as a .glb file.
std::vector<uint8_t> frame_glb(std::string json_text, std::vector<uint8_t> bin) {
  json_text.resize((json_text.size() + 3) & ~size_t(3), ' ');
  bin.resize((bin.size() + 3) & ~size_t(3), 0);
  const size_t total = 12 + 8 + json_text.size() + (bin.empty() ? 0 : 8 + bin.size());
  std::vector<uint8_t> out;
  out.reserve(total);
  put_u32(out, 0x46546C67u);  // "glTF"
  put_u32(out, 2);
  put_u32(out, uint32_t(total));
  put_u32(out, uint32_t(json_text.size()));
  put_u32(out, 0x4E4F534Au);  // "JSON"
  out.insert(out.end(), json_text.begin(), json_text.end());
  if (!bin.empty()) {
    put_u32(out, uint32_t(bin.size()));
    put_u32(out, 0x004E4942u);  // "BIN\0"
    out.insert(out.end(), bin.begin(), bin.end());
  }
  return out;
}

}  // namespace

Mat4d z_up_to_y_up() {
  Mat4d m;
  m << 1, 0, 0, 0,  //
      0, 0, 1, 0,   //
      0, -1, 0, 0,  //
      0, 0, 0, 1;
  return m;  // column-major data: [1,0,0,0, 0,0,-1,0, 0,1,0,0, 0,0,0,1]
}

Mat4d to_matrix(const Affine3f& a) {
  Mat4d m = Mat4d::Identity();
  m.topRows<3>() = a.cast<double>();
  return m;
}

std::vector<nlohmann::json> part_class_extras(const Mesh& mesh, Role node_role, const Ontology& ontology) {
  std::vector<nlohmann::json> extras(mesh.parts.size());
  for (size_t p = 0; p < mesh.parts.size(); ++p)
    if (mesh.parts[p].role != node_role) extras[p] = {{"class_id", ontology.id(mesh.parts[p].role)}};
  return extras;
}

std::vector<uint8_t> encode_glb(const GltfDocument& doc) {
  BinBuilder bin;
  MaterialTable materials(bin);
  json root = {{"asset", {{"version", "2.0"}, {"generator", "Silva"}}}};
  json meshes = json::array();
  for (size_t i = 0; i < doc.meshes.size(); ++i) meshes.push_back(encode_mesh(doc.meshes[i], i, bin, materials));
  json nodes = json::array();
  bool instancing = false;
  for (size_t i = 0; i < doc.nodes.size(); ++i) nodes.push_back(encode_node(doc.nodes[i], i, doc, bin, instancing));
  for (uint32_t r : doc.roots)
    if (r >= doc.nodes.size()) throw InputError("glTF export: root node index " + std::to_string(r) + " is missing");
  if (!meshes.empty()) root["meshes"] = std::move(meshes);
  if (!nodes.empty()) root["nodes"] = std::move(nodes);
  root["scene"] = 0;
  root["scenes"] = json::array({{{"nodes", doc.roots}}});
  if (instancing) root["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
  materials.emit(root);
  if (!bin.views().empty()) {
    bin.bin().resize((bin.bin().size() + 3) & ~size_t(3), 0);
    root["buffers"] = json::array({{{"byteLength", bin.bin().size()}}});
    root["bufferViews"] = bin.views();
    root["accessors"] = bin.accessors();
  }
  return frame_glb(root.dump(), std::move(bin.bin()));
}

void write_glb(const GltfDocument& doc, const std::filesystem::path& path) {
  write_file_atomic(path, std::span<const uint8_t>(encode_glb(doc)));
}

}  // namespace silva::io
