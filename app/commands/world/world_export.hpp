#pragma once
/// @file The world as one glTF document (CONTRACT.md "World export"): root `silva_world` (Z-up to
/// Y-up), terrain chunks by (i, j) (the trail painted in), then objects by instance id.
#include "assets/library.hpp"
#include "core/ontology.hpp"
#include "io/gltf_writer.hpp"
#include "world/world_summary.hpp"

namespace silva::app {

using world::BuiltWorld;

/// Builds the export document of `world` (full-detail meshes, what render.lod = false draws).
/// `instancing`: one EXT_mesh_gpu_instancing node per asset instead of one node per object.
/// The document points into `world` and `library`, which must outlive it.
io::GltfDocument world_document(const BuiltWorld& world, const assets::AssetLibrary& library, const Ontology& ontology,
                                bool instancing);

}  // namespace silva::app
