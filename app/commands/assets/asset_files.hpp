#pragma once
/// @file Writing the built-in asset library: one .glb per asset + library.json (`silva assets build`).
#include <cstdint>
#include <filesystem>

#include "assets/factory.hpp"
#include "assets/library.hpp"
#include "io/gltf_writer.hpp"

namespace silva::app {

/// The glTF document of one asset: root node "<name>" (matrix Z-up -> Y-up) with children
/// "lod0", "lod1", ... each drawing mesh "lodK"; primitives carry extras {"role": "<class>"}.
io::GltfDocument asset_document(const assets::Asset& asset);

/// Generates every built-in variant for `seed` (in parallel) and writes library.json into `out_dir`
/// (created if needed): generator entries, or with `glb` file entries and one "<name>.glb" per
/// asset; at most `max_variants` variants per generator. Returns the library. Throws IoError naming the path.
assets::AssetLibrary build_library(const std::filesystem::path& out_dir, bool glb,
                                   uint64_t seed = assets::kDefaultAssetSeed, uint32_t max_variants = UINT32_MAX);

}  // namespace silva::app
