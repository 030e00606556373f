#pragma once
/// @file Generic binary glTF 2.0 (.glb) writer for Silva meshes (CONTRACT.md "World export").
/// Each mesh part becomes one primitive (POSITION, NORMAL, TEXCOORD_0, indices) with a material
/// named after its core Material; alpha-masked parts get alphaMode MASK, alphaCutoff and an
/// embedded PNG baseColorTexture holding the mask in alpha (sampler nearest/repeat). Nodes carry
/// a column-major matrix, extras and children; several nodes may share one mesh; a node may draw
/// many copies through EXT_mesh_gpu_instancing. The bytes are a pure function of the document.
///
/// The JSON chunk is built with nlohmann-json rather than tinygltf's serializer: tinygltf 2.7's
/// Value holds only 32-bit signed integers, and instance ids (uint32) must stay JSON integers.
/// The output is read back with tinygltf in the tests.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/mesh.hpp"
#include "core/ontology.hpp"
#include "core/types.hpp"

namespace silva::io {

/// One glTF mesh: a Silva mesh whose parts become primitives (parts with no indices are skipped).
struct GltfMesh {
  std::string name;                         ///< Mesh name.
  const Mesh* mesh = nullptr;               ///< Geometry (non-owning, must outlive the write).
  std::vector<nlohmann::json> part_extras;  ///< Empty, or one per part (null = no extras).
};

/// One copy drawn by EXT_mesh_gpu_instancing: a similarity transform (rotation, uniform scale,
/// translation) and the ids written as the float attributes _CLASS_ID, _INSTANCE_ID_HI/_LO.
struct GltfInstance {
  Affine3f transform = Affine3f::Identity();  ///< Instance to node space [sR|t].
  uint32_t class_id = 0;                      ///< Class id (fits 16 bits).
  uint32_t instance_id = 0;                   ///< Packed instance id, split into two 16-bit halves.
};

/// One node of the node tree.
struct GltfNode {
  std::string name;                    ///< Node name.
  Mat4d matrix = Mat4d::Identity();    ///< Local transform (written unless identity).
  int mesh = -1;                       ///< Index into GltfDocument::meshes, or -1.
  std::vector<uint32_t> children;      ///< Child node indices.
  nlohmann::json extras;               ///< Node extras (null = none).
  std::vector<GltfInstance> instances; ///< Non-empty: EXT_mesh_gpu_instancing copies of `mesh`.
};

/// A whole glTF document: meshes, nodes and the scene's root nodes, in output order.
struct GltfDocument {
  std::vector<GltfMesh> meshes;   ///< Meshes.
  std::vector<GltfNode> nodes;    ///< Nodes (children refer to indices here).
  std::vector<uint32_t> roots;    ///< Root nodes of the single scene.
};

/// Column-major root matrix turning Silva's Z-up world into glTF's Y-up (CONTRACT.md).
Mat4d z_up_to_y_up();

/// A 4x4 matrix from a 3x4 affine [R|t].
Mat4d to_matrix(const Affine3f& m);

/// Primitive extras {"class_id": id} for the parts of `mesh` whose role differs from `node_role`
/// (null for the others), as the world export writes them (canopy primitives of a trunk node).
std::vector<nlohmann::json> part_class_extras(const Mesh& mesh, Role node_role, const Ontology& ontology);

/// Encodes the document as .glb bytes. Throws InputError for an inconsistent document
/// (bad mesh/node index, a mesh with no triangles, an index out of range).
std::vector<uint8_t> encode_glb(const GltfDocument& doc);

/// Writes the document to `path` atomically (temp file + rename). Throws IoError naming the path.
void write_glb(const GltfDocument& doc, const std::filesystem::path& path);

}  // namespace silva::io
