#pragma once
/// @file Loading an asset library (library.json + mesh files) through assimp, so users can add
/// or replace assets with their own glTF/FBX/OBJ files and class tags.
#include <filesystem>

#include "assets/library.hpp"

namespace silva::assets {

/// Loads every asset listed in `library_json` (schema in assets/manifest.hpp). A file with fewer
/// levels than thresholds + 1 gets the missing levels built with build_lods; extra thresholds
/// beyond the levels it can build are dropped. Throws InputError naming the file and key for a
/// bad manifest or a missing, corrupt or untagged asset.
AssetLibrary load_library(const std::filesystem::path& library_json);

}  // namespace silva::assets
