#pragma once
/// @file Loading an asset library (library.json + mesh files) through assimp, so users can add
/// or replace assets with their own glTF/FBX/OBJ files and class tags.
#include <filesystem>

#include "assets/library.hpp"
#include "core/season.hpp"

namespace silva::assets {

/// Loads every asset listed in `library_json` (schema in assets/manifest.hpp). A generator entry
/// names a built-in procedural variant: its metadata is read now and its meshes are generated when
/// first used (assets::lazy_asset). A file holding a
/// single level gets further levels built with build_lods (one per threshold, at most 3); the
/// asset keeps min(levels, thresholds + 1) levels and as many thresholds as it has extra levels.
/// Generator entries are dressed for `season` (dress_for_season); file entries are the user's own
/// and stay as they are. Throws InputError naming the file and key for a bad manifest or a
/// missing, corrupt or untagged asset.
AssetLibrary load_library(const std::filesystem::path& library_json, Season season = Season::Summer);

}  // namespace silva::assets
