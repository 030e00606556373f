#pragma once
/// @file How many triangles a glTF file declares, counted from its JSON, so the importer can tell
/// when assimp dropped some (it skips a face whose index is out of range without a word).
#include <cstdint>
#include <filesystem>
#include <optional>

namespace silva::assets {

/// The triangles the meshes of a glTF (.gltf text or .glb binary) file declare: per primitive of mode
/// 4 (triangles) its index count / 3, of mode 5 or 6 (strip, fan) count − 2, where count is the index
/// accessor's or else the POSITION accessor's. nullopt when the file is not glTF or its JSON cannot be read
/// (then assimp's own error stands).
std::optional<uint64_t> gltf_declared_triangles(const std::filesystem::path& file);

}  // namespace silva::assets
