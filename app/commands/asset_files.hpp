#pragma once
/// @file Writing the built-in asset library: one .glb per asset + library.json (`silva assets build`).
#include <filesystem>

#include "assets/factory.hpp"
#include "assets/library.hpp"
#include "io/gltf_writer.hpp"

namespace silva::app {

/// The glTF document of one asset: root node "<name>" (matrix Z-up -> Y-up) with children
/// "lod0", "lod1", ... each drawing mesh "lodK"; primitives carry extras {"role": "<class>"}.
io::GltfDocument asset_document(const assets::Asset& asset);

/// Generates the built-in library for `seed`, writes "<name>.glb" per asset and library.json
/// into `out_dir` (created if needed) and returns the library. Throws IoError naming the path.
assets::AssetLibrary build_library(const std::filesystem::path& out_dir, uint64_t seed = assets::kDefaultAssetSeed);

}  // namespace silva::app
