#pragma once
/// @file The synthetic forest the rasteriser benches draw: 128 m x 128 m terrain at 0.5 m (16 chunks)
/// + 300 instanced trees of three variants with alpha-tested leaf cards, seen at 1920x1080.
#include <memory>
#include <vector>

#include "core/camera.hpp"
#include "core/mesh.hpp"
#include "render/scene.hpp"

namespace silva::bench {

/// The bench world: 16 terrain chunks (one instance each), 3 tree meshes, ~300 tree instances.
/// Fixed seeds: the same scene and camera on every run.
struct ForestScene {
  std::vector<std::unique_ptr<Mesh>> meshes;  ///< Owned meshes (scene.meshes point into them).
  render::Scene scene;                        ///< Drawable scene (single LOD per mesh).
  Camera camera;                              ///< The 1920x1080 view across the patch.
  /// Builds the scene.
  ForestScene();
  /// Triangles of all instances (what every renderer of the scene is given).
  size_t triangle_count() const;
};

/// The shared scene, built on first use.
const ForestScene& forest_scene();

}  // namespace silva::bench
