#pragma once
/// @file Importing an asset file's LOD meshes through assimp (glTF/GLB, FBX, OBJ, ...).
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/mesh.hpp"

namespace silva::assets {

/// Imports the LODs of one asset file. Nodes named "lod0", "lod1", ... are the levels (in that
/// order); a file with no such node is a single level. Every assimp mesh under a level becomes
/// one part, transformed by its node's global transform; its role is `parts[material name]`, its
/// Material the core material of that name (else the role's usual one), its alpha mask the alpha
/// channel of the base-colour/diffuse texture (embedded, or a file next to the asset) unless the
/// glTF alphaMode is OPAQUE. Y-up files (the glTF/assimp convention) are turned to Silva's Z up
/// unless `z_up`. `where` names the manifest key in messages. Throws InputError naming the file
/// for a missing/unreadable file, a file without triangles or a part whose material has no class.
std::vector<Mesh> import_asset_lods(const std::filesystem::path& file, const std::map<std::string, Role>& parts,
                                    bool z_up, const std::string& where);

}  // namespace silva::assets
