#pragma once
/// @file library.json, the asset library manifest (schema in assets/README.md):
///
///   {"format": "silva-asset-library", "version": 1, "assets": [{
///     "name": "spruce_00",              unique asset name
///     "file": "spruce_00.glb",          mesh file relative to library.json (.glb/.gltf/.fbx/.obj ...)
///       or, for a built-in procedural variant (made when first drawn), instead of file/up_axis/parts:
///     "generator": "spruce", "variant": 0, "seed": "0x5117a0a55e7"
///     "kind": "conifer_tree",           conifer_tree|broadleaf_tree|dead_tree|stump|grass|fern|shrub|rock|log
///     "class": "tree_trunk",            role of the object node (ontology role name)
///     "up_axis": "y",                   optional: "y" (default; glTF/assimp convention) or "z" (Silva)
///     "parts": {"bark_spruce": "tree_trunk", "needles_spruce": "tree_canopy"},  material name -> role
///     "collision": {"shape": "cylinder", "center": [x,y,z], "radius": r, "height": h, "axis": [0,0,1]},
///                  sphere: center, radius; box: center, half_extents; capsule: as cylinder
///                  (height = length of the core segment); none: no other key
///     "lod_screen_sizes": [0.25, 0.1, 0.04]   one per LOD after the first, descending, in (0, 1]
///   }, ...]}
#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "assets/library.hpp"

namespace silva::assets {

/// One asset's entry in library.json.
struct ManifestEntry {
  std::string name;                     ///< Unique asset name.
  std::string file;                     ///< Mesh file, relative to the manifest's folder ("" for a generator entry).
  std::optional<ProceduralSource> source;  ///< Generator entry: the built-in variant it names.
  AssetKind kind = AssetKind::Rock;     ///< Placement kind.
  Role role = Role::Obstacle;           ///< Class of the object node.
  bool z_up = false;                    ///< File already in Silva's Z-up axes ("up_axis": "z").
  std::map<std::string, Role> parts;    ///< Material name -> class of the parts using it.
  CollisionProxy proxy;                 ///< Collision proxy.
  std::vector<float> lod_screen_sizes;  ///< LOD thresholds (fraction of image height).
};

/// The manifest entry of a generated asset (parts mapping from its materials' names).
/// Throws InputError if one material name is used with two roles.
ManifestEntry manifest_entry(const Asset& asset);

/// The text of library.json for `entries` (deterministic bytes; writing it is the caller's, through io).
std::string manifest_text(std::span<const ManifestEntry> entries);

/// Reads and validates library.json; throws InputError naming the file and key on any problem.
std::vector<ManifestEntry> read_manifest(const std::filesystem::path& path);

/// Parses the text of a manifest read from `path` (named in every error); what read_manifest does
/// after reading the file.
std::vector<ManifestEntry> parse_manifest(const std::string& text, const std::filesystem::path& path);

}  // namespace silva::assets
