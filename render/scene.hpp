#pragma once
/// @file What the renderer draws: meshes with LODs and placed instances. No ECS, no files.
#include <vector>

#include "core/mesh.hpp"
#include "core/types.hpp"

namespace silva::render {

/// A drawable mesh with its levels of detail (lods[0] = full detail).
struct MeshLods {
  std::vector<const Mesh*> lods;          ///< Non-owning; lods[0] is full detail.
  /// LOD k (k >= 1) is used when the instance's projected bounding-sphere diameter, as a
  /// fraction of image height, is below lod_screen_sizes[k-1]. Size lods.size()-1, descending.
  std::vector<float> lod_screen_sizes;
  /// Object-space bounds of all LODs, used for culling and LOD selection. Left empty, the
  /// renderer computes them every pass; call compute_bounds() once to cache them here.
  AABB bounds;
  /// Drawn by the shadow pass in place of any level with more triangles (its alpha cards thinned;
  /// shadows are RGB only, so no label depends on it); null: the levels themselves.
  const Mesh* shadow_caster = nullptr;
  /// Object-space bounds of shadow_caster (filled by compute_bounds; empty: computed each pass).
  AABB shadow_bounds;
  /// Fills `bounds` from the positions of every LOD, and `shadow_bounds` from shadow_caster.
  void compute_bounds() {
    bounds = AABB{};
    for (const Mesh* m : lods)
      if (m) bounds.extend(m->bounds());
    shadow_bounds = shadow_caster ? shadow_caster->bounds() : AABB{};
  }
  /// The mesh of level `lod`: lods[lod], or shadow_caster for lod == lods.size().
  const Mesh& level(uint32_t lod) const { return lod < lods.size() ? *lods[lod] : *shadow_caster; }
};

/// One placed copy of a mesh.
struct Instance {
  Affine3f object_to_world = Affine3f::Identity();  ///< [R|t], may include uniform scale.
  uint32_t mesh = 0;         ///< Index into Scene::meshes.
  uint32_t instance_id = 0;  ///< Packed instance id (0 = stuff: terrain, trail, ground vegetation).
  uint32_t variation = 0;    ///< Per-instance seed for colour variation in shading.
};

/// Everything one frame may draw.
struct Scene {
  std::vector<MeshLods> meshes;     ///< Drawable meshes.
  std::vector<Instance> instances;  ///< Placed instances.
};

}  // namespace silva::render
