#pragma once
/// @file The asset library: every placeable mesh variant with its LODs, classes and collision proxy.
/// Built by `silva assets build` (procedural generators -> .glb + library.json) and loaded
/// through assimp by assets::load_library, so users can add or replace assets.
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
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

/// An asset's LOD meshes (lods[0] full detail), either given when loaded or made on first use
/// by a procedural generator; thread-safe, and the same whichever thread makes them.
class AssetGeometry {
 public:
  /// Makes the LOD meshes; called at most once.
  using Make = std::function<std::vector<Mesh>()>;
  /// Geometry that is ready now.
  explicit AssetGeometry(std::vector<Mesh> lods);
  /// Geometry that `make` produces on first use.
  explicit AssetGeometry(Make make);
  /// The LOD meshes (made now when this is the first use).
  const std::vector<Mesh>& lods() const;
  /// What the sun's shadow map draws: LOD 1 (or lods()[0] without one) with its alpha cards
  /// thinned to kShadowCardRatio (shadows are RGB only, so no label depends on it); lods()[0]
  /// itself when that has no card part. Made on first use.
  const Mesh& shadow_caster() const;

 private:
  mutable std::once_flag once_;
  mutable std::vector<Mesh> lods_;
  Make make_;
  mutable std::once_flag shadow_once_;
  mutable std::optional<Mesh> shadow_caster_;  ///< Empty when lods()[0] is its own caster.
};

/// Where a procedural variant comes from: generator (factory prefix), variant index and seed.
struct ProceduralSource {
  std::string generator;  ///< Factory prefix, e.g. "norway_spruce".
  uint32_t variant = 0;   ///< Variant index.
  uint64_t seed = 0;      ///< Asset seed.
};

/// One asset variant: its LOD meshes and metadata (placement only needs the metadata, so a
/// procedural variant's meshes are made when it is first drawn).
struct Asset {
  std::string name;                 ///< Unique name, e.g. "spruce_03".
  std::string file;                 ///< .glb/.fbx/.obj file relative to the library folder ("" = procedural).
  std::optional<ProceduralSource> source;  ///< Set for built-in procedural variants.
  AssetKind kind = AssetKind::Rock; ///< Placement kind.
  Role role = Role::Obstacle;       ///< Class of the object node (trunk for trees).
  std::shared_ptr<const AssetGeometry> geometry;  ///< LOD meshes; parts carry their own roles (canopy).
  std::vector<float> lod_screen_sizes;  ///< Thresholds, see render::MeshLods (one per LOD after the first).
  CollisionProxy proxy;             ///< Solid proxy (None for ground vegetation).
  /// The LOD meshes (lods()[0] full detail), made on first use for a procedural variant.
  const std::vector<Mesh>& lods() const { return geometry->lods(); }
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
