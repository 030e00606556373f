#pragma once
/// @file `silva verify`'s geometry for a dataset rendered with `render.lod = true`: each instance at the
/// level the rasteriser drew it for the frame's camera, so the certificate checks the files against the
/// triangles they show (full-detail casting measures the LOD's simplification error instead).
#include <cstdint>
#include <memory>
#include <vector>

#include "core/camera.hpp"
#include "raycast/ray_scene.hpp"
#include "systems/prepare_scene.hpp"

namespace silva::app {

/// The instances of `frame` (the scene prepare_scene builds from the camera's eye) that the renderer
/// draws through `camera`, each with the mesh of the level it picks (render::select_instances, LOD on);
/// instances it culls are left out. The meshes are `frame`'s, which must outlive the result's use.
std::vector<raycast::RayInstance> drawn_instances(const systems::FrameScene& frame, const Camera& camera);

/// A ray-cast scene that holds one frame's drawn instances at a time; a mesh's BVH is kept while
/// consecutive frames draw it.
class DrawnRayScene {
 public:
  /// Replaces the scene's instances by `frame`'s drawn through `camera`, and commits.
  void show(systems::FrameScene frame, const Camera& camera);
  /// The committed scene.
  const raycast::RayScene& scene() const { return *scene_; }

 private:
  std::unique_ptr<raycast::RayScene> scene_ = std::make_unique<raycast::RayScene>();
  systems::FrameScene frame_;  ///< Owner of the shown meshes (terrain chunks).
  uint64_t key_ = 0;           ///< Group key of the shown frame (alternates, so shared BVHs stay).
};

}  // namespace silva::app
