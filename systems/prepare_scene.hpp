#pragma once
/// @file Prepare phase: the active view's chunks, from the chunk cache, as a render::Scene
/// (system "prepare_scene"), and the SceneBuilder that turns chunks + assets into scenes.
#include <memory>
#include <vector>

#include "assets/library.hpp"
#include "ecs/world.hpp"
#include "raycast/ray_scene.hpp"
#include "render/scene.hpp"
#include "world/chunk_content.hpp"

namespace silva::systems {

/// A scene plus the chunk contents its meshes point into (kept alive while it is drawn).
struct FrameScene {
  render::Scene scene;                                        ///< What the renderer draws.
  std::vector<std::shared_ptr<const ChunkContent>> chunks;    ///< Owners of the terrain meshes.
};

/// A chunk's instances for the ray caster.
struct ChunkRays {
  std::vector<raycast::RayInstance> solid;         ///< Terrain, trees, shrubs, rocks, logs: always visible.
  std::vector<raycast::RayInstance> ground_cover;  ///< Grass, ferns, debris: each with its cut-off and anchor.
};

/// Builds frame scenes; asset meshes come first (mesh index = asset index), then per-chunk
/// terrain (with its coarse level as LOD 1; the trail is painted into it). Stuff (terrain, trail,
/// grass, ferns) has instance id 0.
class SceneBuilder {
 public:
  /// A builder for `library`'s assets (which must outlive it); no asset meshes are made yet.
  explicit SceneBuilder(const assets::AssetLibrary& library);
  /// Scene of the given chunks seen from `eye`: terrain (trail included) and every object of each,
  /// in chunk order, but ground cover (grass, ferns, debris) beyond its ground_cover_cutoff. Makes
  /// the meshes of assets drawn for the first time (in parallel); copies of the builder share them.
  FrameScene build(std::vector<std::shared_ptr<const ChunkContent>> chunks, const Vec3d& eye,
                   double ground_cover_distance) const;
  /// The same chunk for the ray caster at full detail: its terrain and objects, and apart from them
  /// its ground cover, carrying the cut-off build() applies (measured from each cast's eye). Makes
  /// missing meshes.
  ChunkRays ray_instances(const ChunkContent& chunk, double ground_cover_distance) const;

 private:
  /// The instance of a placed object (its mesh index is its asset).
  static render::Instance object_instance(const Vegetation& v);
  /// Fills the drawable meshes of the assets instances[first..] draw that have none yet.
  void make_drawable(const std::vector<render::Instance>& instances, size_t first) const;

  const assets::AssetLibrary* library_;
  std::shared_ptr<std::vector<render::MeshLods>> asset_meshes_;  ///< Per asset; empty until first drawn.
  std::vector<uint8_t> ground_cover_;  ///< Per asset: 1 for grass, ferns and ground-cover debris.
};

/// Per-instance colour-variation seed derived from an object's position (stable across runs).
uint32_t variation_seed(const Vec3f& position);

/// Distance from the camera beyond which the ground-cover object with variation seed `variation`
/// is not drawn: between 75 % and 100 % of render.ground_cover_distance (no visible line).
double ground_cover_cutoff(uint32_t variation, double ground_cover_distance);

/// Resource: the scene the Render phase draws for the active camera (left as it was without one).
struct PreparedScene {
  FrameScene frame;  ///< Scene and the chunk contents it points into.
  /// With a view fan (ViewChunks::fan): the scene of the fan's chunks, which the frame's sun passes draw so
  /// that every frame of the fan gets the same shadow map; kept while the fan's chunks and eye stay the
  /// same. Null without a fan: the sun passes draw `frame`.
  std::shared_ptr<const FrameScene> fan;
  std::vector<ChunkCoord> fan_coords;  ///< The chunks `fan` holds.
  Vec3d fan_eye = Vec3d::Zero();       ///< The eye `fan` was built for (its ground-cover cut-off).
  /// The scene the sun passes draw: `fan`, else `frame`'s.
  const render::Scene& sun_scene() const { return fan ? fan->scene : frame.scene; }
};

/// Registers "prepare_scene" (phase Prepare): takes the ViewChunks from the ChunkCache resource
/// (most recently used, evicting beyond capacity) and builds the PreparedScene resource.
void install_prepare_scene(ecs::World& world, const assets::AssetLibrary& library);

}  // namespace silva::systems
