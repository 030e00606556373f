#pragma once
/// @file The asset library: every placeable mesh variant with its LODs, classes and collision proxy.
/// Built by `silva assets build` (procedural generators -> .glb + library.json) and loaded
/// through assimp by assets::load_library, so users can add or replace assets.
#include <memory>
#include <string>
#include <vector>

#include "core/asset_kind.hpp"
#include "core/mesh.hpp"
#include "core/ontology.hpp"

namespace silva::assets {

using silva::AssetKind;

/// Collision proxy shape in object space (Z up, origin at the object's ground contact point).
struct CollisionProxy {
  enum class Shape : uint8_t { None, Cylinder, Capsule, Box, Sphere };
  Shape shape = Shape::None;        ///< None: no proxy (ground vegetation).
  Vec3f center = Vec3f::Zero();     ///< Proxy centre in object space.
  float radius = 0;                 ///< Cylinder/capsule/sphere radius (m).
  float height = 0;                 ///< Cylinder/capsule length along the axis (m).
  Vec3f half_extents = Vec3f::Zero();  ///< Box half extents (m).
  Vec3f axis = Vec3f::UnitZ();      ///< Cylinder/capsule axis (unit, object space).
  /// Radius of the proxy's footprint circle on the ground plane around the object origin.
  float footprint_radius() const;
};

/// One asset variant: its LOD meshes (lods[0] full detail) and metadata.
struct Asset {
  std::string name;                 ///< Unique name, e.g. "conifer_03".
  std::string file;                 ///< .glb/.fbx/.obj file, relative to the library folder.
  AssetKind kind = AssetKind::Rock; ///< Placement kind.
  Role role = Role::Obstacle;       ///< Class of the object node (trunk for trees).
  std::vector<Mesh> lods;           ///< LOD meshes; parts carry their own roles (canopy).
  std::vector<float> lod_screen_sizes;  ///< Thresholds, see render::MeshLods.
  CollisionProxy proxy;             ///< Solid proxy (None for ground vegetation).
};

/// All assets, with per-kind index lists for placement.
struct AssetLibrary {
  std::vector<Asset> assets;                      ///< Every variant.
  std::vector<uint32_t> by_kind[size_t(AssetKind::Count)];  ///< Asset indices per kind.
  /// Rebuilds by_kind from assets (in asset order).
  void index_kinds();
};

/// Name of a kind ("conifer_tree") as used in library.json.
const char* kind_name(AssetKind k);

/// Parses a kind name; returns false if unknown.
bool parse_kind(const std::string& name, AssetKind& out);

}  // namespace silva::assets
