#include "io/gltf_writer.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <tiny_gltf.h>

#include "core/error.hpp"

namespace silva::io {
namespace {

/// A 4x4 checker mask (opaque where x + y is even).
std::shared_ptr<const AlphaMask> checker_mask() {
  auto m = std::make_shared<AlphaMask>();
  m->width = m->height = 4;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) m->alpha.push_back((x + y) % 2 == 0 ? 255 : 0);
  m->cutoff = 0.5f;
  m->feature_length = 0.25f;
  return m;
}

/// A tree-like mesh: one trunk triangle and one masked canopy card (two triangles).
Mesh tree_mesh(const std::shared_ptr<const AlphaMask>& mask) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, 3}, {-1, 0, 2}, {1, 0, 2}, {1, 0, 4}, {-1, 0, 4}};
  m.normals.assign(m.positions.size(), Vec3f(0, -1, 0));
  m.uvs = {{0, 0}, {1, 0}, {0, 1}, {0, 1}, {1, 1}, {1, 0}, {0, 0}};
  m.indices = {0, 1, 2, 3, 4, 5, 3, 5, 6};
  MeshPart trunk;
  trunk.index_count = 3;
  trunk.role = Role::TreeTrunk;
  trunk.material = Material::BarkConifer;
  MeshPart canopy;
  canopy.first_index = 3;
  canopy.index_count = 6;
  canopy.role = Role::TreeCanopy;
  canopy.material = Material::Needles;
  canopy.mask = mask;
  canopy.double_sided = true;
  m.parts = {trunk, canopy};
  return m;
}

/// The JSON chunk of a .glb.
nlohmann::json json_chunk(const std::vector<uint8_t>& glb) {
  uint32_t len;
  std::memcpy(&len, glb.data() + 12, 4);
  return nlohmann::json::parse(glb.begin() + 20, glb.begin() + 20 + len);
}

/// Floats of an accessor (tightly packed float accessor).
std::vector<float> floats(const tinygltf::Model& m, int accessor) {
  const auto& a = m.accessors[size_t(accessor)];
  const auto& v = m.bufferViews[size_t(a.bufferView)];
  const size_t comps = a.type == TINYGLTF_TYPE_SCALAR ? 1 : a.type == TINYGLTF_TYPE_VEC2 ? 2 : a.type == TINYGLTF_TYPE_VEC3 ? 3 : 4;
  std::vector<float> out(a.count * comps);
  std::memcpy(out.data(), m.buffers[0].data.data() + v.byteOffset + a.byteOffset, out.size() * sizeof(float));
  return out;
}

class GltfWriterTest : public ::testing::Test {
 protected:
  void SetUp() override {
    mesh_ = tree_mesh(checker_mask());
    doc_.meshes.push_back({"tree", &mesh_, part_class_extras(mesh_, Role::TreeTrunk, default_ontology())});
    GltfNode root;
    root.name = "silva_world";
    root.matrix = z_up_to_y_up();
    root.children = {1, 2};
    doc_.nodes.push_back(root);
    for (uint32_t id : {0x00010001u, 0xFF020003u}) {  // the second needs all 32 bits
      GltfNode n;
      n.name = "tree_" + std::to_string(id);
      n.mesh = 0;
      Affine3f t = Affine3f::Identity();
      t(0, 3) = float(id & 0xff);
      n.matrix = to_matrix(t);
      n.extras = {{"class_id", 3}, {"instance_id", id}};
      doc_.nodes.push_back(n);
    }
    doc_.roots = {0};
  }
  tinygltf::Model parse(const std::vector<uint8_t>& glb) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    const bool ok = loader.LoadBinaryFromMemory(&model, &err, &warn, glb.data(), unsigned(glb.size()));
    EXPECT_TRUE(ok) << err << warn;
    return model;
  }
  Mesh mesh_;
  GltfDocument doc_;
};

TEST_F(GltfWriterTest, ParsesBackWithTinygltf) {
  const std::vector<uint8_t> glb = encode_glb(doc_);
  ASSERT_EQ(glb.size() % 4, 0u);
  ASSERT_EQ(std::memcmp(glb.data(), "glTF", 4), 0);
  const tinygltf::Model m = parse(glb);
  ASSERT_EQ(m.nodes.size(), 3u);
  EXPECT_EQ(m.nodes[0].name, "silva_world");
  EXPECT_EQ(m.nodes[0].matrix, std::vector<double>({1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1}));
  EXPECT_EQ(m.nodes[0].children, std::vector<int>({1, 2}));
  EXPECT_EQ(m.nodes[1].mesh, 0);  // both objects share one mesh
  EXPECT_EQ(m.nodes[2].mesh, 0);
  EXPECT_EQ(m.nodes[1].matrix[12], 1.0);  // translation x in column-major slot 12
  EXPECT_EQ(m.nodes[1].extras.Get("class_id").GetNumberAsInt(), 3);
  ASSERT_EQ(m.scenes.size(), 1u);
  EXPECT_EQ(m.scenes[0].nodes, std::vector<int>({0}));

  ASSERT_EQ(m.meshes.size(), 1u);
  const auto& prims = m.meshes[0].primitives;
  ASSERT_EQ(prims.size(), 2u);
  EXPECT_FALSE(prims[0].extras.IsObject());  // trunk: node's own class
  EXPECT_EQ(prims[1].extras.Get("class_id").GetNumberAsInt(), 4);  // canopy
  for (const auto& p : prims) {
    EXPECT_EQ(p.mode, TINYGLTF_MODE_TRIANGLES);
    EXPECT_TRUE(p.attributes.count("POSITION") && p.attributes.count("NORMAL") && p.attributes.count("TEXCOORD_0"));
  }
  EXPECT_EQ(m.accessors[size_t(prims[1].indices)].count, 6u);
  const auto& pos = m.accessors[size_t(prims[0].attributes.at("POSITION"))];
  EXPECT_EQ(pos.minValues, std::vector<double>({-1, 0, 0}));
  EXPECT_EQ(pos.maxValues, std::vector<double>({1, 0, 4}));
  const std::vector<float> p = floats(m, prims[0].attributes.at("POSITION"));
  EXPECT_EQ(std::memcmp(p.data(), mesh_.positions.data(), p.size() * sizeof(float)), 0);

  ASSERT_EQ(m.materials.size(), 2u);
  const auto& bark = m.materials[size_t(prims[0].material)];
  const auto& needles = m.materials[size_t(prims[1].material)];
  EXPECT_EQ(bark.name, "bark_conifer");
  EXPECT_EQ(bark.alphaMode, "OPAQUE");
  EXPECT_FALSE(bark.doubleSided);
  EXPECT_EQ(needles.name, "needles");
  EXPECT_EQ(needles.alphaMode, "MASK");
  EXPECT_EQ(needles.alphaCutoff, 0.5);
  EXPECT_EQ(needles.extras.Get("leaf_length_uv").GetNumberAsDouble(), 0.25);
  EXPECT_FALSE(bark.extras.IsObject());
  EXPECT_TRUE(needles.doubleSided);
  const int tex = needles.pbrMetallicRoughness.baseColorTexture.index;
  ASSERT_GE(tex, 0);
  const auto& sampler = m.samplers[size_t(m.textures[size_t(tex)].sampler)];
  EXPECT_EQ(sampler.magFilter, TINYGLTF_TEXTURE_FILTER_NEAREST);
  EXPECT_EQ(sampler.minFilter, TINYGLTF_TEXTURE_FILTER_NEAREST);
  EXPECT_EQ(sampler.wrapS, TINYGLTF_TEXTURE_WRAP_REPEAT);
  EXPECT_EQ(sampler.wrapT, TINYGLTF_TEXTURE_WRAP_REPEAT);
  const auto& img = m.images[size_t(m.textures[size_t(tex)].source)];
  EXPECT_EQ(img.mimeType, "image/png");
  ASSERT_EQ(img.width, 4);
  ASSERT_EQ(img.component, 4);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(img.image[size_t(4 * i + 3)], mesh_.parts[1].mask->alpha[size_t(i)]) << i;
}

TEST_F(GltfWriterTest, InstanceIdsStayJsonIntegers) {
  const nlohmann::json j = json_chunk(encode_glb(doc_));
  EXPECT_TRUE(j["nodes"][2]["extras"]["instance_id"].is_number_unsigned());
  EXPECT_EQ(j["nodes"][2]["extras"]["instance_id"].get<uint32_t>(), 0xFF020003u);
  EXPECT_EQ(j["asset"]["version"], "2.0");
  // Vertex bufferViews carry their target; every bufferView starts 4-byte aligned.
  for (const auto& v : j["bufferViews"]) EXPECT_EQ(v["byteOffset"].get<size_t>() % 4, 0u);
}

TEST_F(GltfWriterTest, BytesAreDeterministic) {
  EXPECT_EQ(encode_glb(doc_), encode_glb(doc_));
  Mesh other = mesh_;
  other.positions[0].x() = 0.5f;
  GltfDocument d2 = doc_;
  d2.meshes[0].mesh = &other;
  EXPECT_NE(encode_glb(doc_), encode_glb(d2));
}

TEST_F(GltfWriterTest, GpuInstancingWritesIdsAsSixteenBitFloats) {
  GltfNode inst;
  inst.name = "instanced";
  inst.mesh = 0;
  for (uint32_t k = 0; k < 3; ++k) {
    Affine3f t = Affine3f::Identity();
    t.leftCols<3>() = 2.0f * Eigen::AngleAxisf(0.5f * float(k), Vec3f::UnitZ()).toRotationMatrix();
    t(1, 3) = float(k);
    inst.instances.push_back({t, 3, 0xFE000001u + k});
  }
  doc_.nodes.push_back(inst);
  doc_.roots.push_back(3);
  const tinygltf::Model m = parse(encode_glb(doc_));
  ASSERT_EQ(m.extensionsUsed, std::vector<std::string>({"EXT_mesh_gpu_instancing"}));
  const auto& ext = m.nodes[3].extensions.at("EXT_mesh_gpu_instancing").Get("attributes");
  const auto hi = floats(m, ext.Get("_INSTANCE_ID_HI").GetNumberAsInt());
  const auto lo = floats(m, ext.Get("_INSTANCE_ID_LO").GetNumberAsInt());
  const auto cls = floats(m, ext.Get("_CLASS_ID").GetNumberAsInt());
  const auto scale = floats(m, ext.Get("SCALE").GetNumberAsInt());
  const auto rot = floats(m, ext.Get("ROTATION").GetNumberAsInt());
  const auto tr = floats(m, ext.Get("TRANSLATION").GetNumberAsInt());
  ASSERT_EQ(hi.size(), 3u);
  for (uint32_t k = 0; k < 3; ++k) {
    EXPECT_EQ((uint32_t(hi[k]) << 16) | uint32_t(lo[k]), 0xFE000001u + k);
    EXPECT_EQ(cls[k], 3.0f);
    EXPECT_NEAR(scale[3 * k], 2.0f, 1e-6f);
    EXPECT_NEAR(rot[4 * k + 2], std::sin(0.25f * float(k)), 1e-6f);  // quaternion z of a yaw
    EXPECT_EQ(tr[3 * k + 1], float(k));
  }
}

TEST_F(GltfWriterTest, InconsistentDocumentsAreInputErrors) {
  GltfDocument bad = doc_;
  bad.nodes[1].mesh = 5;
  EXPECT_THROW(encode_glb(bad), InputError);
  bad = doc_;
  bad.nodes[0].children = {9};
  EXPECT_THROW(encode_glb(bad), InputError);
  Mesh broken = mesh_;
  broken.indices[0] = 99;
  bad = doc_;
  bad.meshes[0].mesh = &broken;
  EXPECT_THROW(encode_glb(bad), InputError);
}

TEST_F(GltfWriterTest, UnwritablePathIsIoError) {
  EXPECT_THROW(write_glb(doc_, "/nonexistent_dir_silva/x.glb"), IoError);
}

}  // namespace
}  // namespace silva::io
