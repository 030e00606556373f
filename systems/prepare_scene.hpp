#pragma once
/// @file Prepare phase: the active view's chunks, from the chunk cache, as a render::Scene
/// (system "prepare_scene"), and the SceneBuilder that turns chunks + assets into scenes.
#include <memory>
#include <vector>

#include "assets/library.hpp"
#include "ecs/world.hpp"
#include "render/scene.hpp"
#include "world/chunk_content.hpp"

namespace silva::systems {

/// A scene plus the chunk contents its meshes point into (kept alive while it is drawn).
struct FrameScene {
  render::Scene scene;                                        ///< What the renderer draws.
  std::vector<std::shared_ptr<const ChunkContent>> chunks;    ///< Owners of terrain/trail meshes.
};

/// Builds frame scenes; asset meshes come first (mesh index = asset index), then per-chunk
/// terrain (with its coarse level as LOD 1) and trail meshes. Stuff (terrain, trail, grass,
/// ferns) has instance id 0.
class SceneBuilder {
 public:
  /// Registers every asset's LODs as drawable meshes.
  explicit SceneBuilder(const assets::AssetLibrary& library);
  /// Scene of the given chunks seen from `eye`: terrain, trail piece and every object of each, in
  /// chunk order, but ground cover (grass, ferns) beyond its ground_cover_cutoff.
  FrameScene build(std::vector<std::shared_ptr<const ChunkContent>> chunks, const Vec3d& eye,
                   double ground_cover_distance) const;

 private:
  std::vector<render::MeshLods> asset_meshes_;
  std::vector<uint8_t> ground_cover_;  ///< Per asset: 1 for grass and ferns.
};

/// Per-instance colour-variation seed derived from an object's position (stable across runs).
uint32_t variation_seed(const Vec3f& position);

/// Distance from the camera beyond which the ground-cover object with variation seed `variation`
/// is not drawn: between 75 % and 100 % of render.ground_cover_distance (no visible line).
double ground_cover_cutoff(uint32_t variation, double ground_cover_distance);

/// Resource: the scene the Render phase draws for the active camera (left as it was without one).
struct PreparedScene {
  FrameScene frame;  ///< Scene and the chunk contents it points into.
};

/// Registers "prepare_scene" (phase Prepare): takes the ViewChunks from the ChunkCache resource
/// (most recently used, evicting beyond capacity) and builds the PreparedScene resource.
void install_prepare_scene(ecs::World& world, const assets::AssetLibrary& library);

}  // namespace silva::systems
