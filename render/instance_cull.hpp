#pragma once
/// @file Per-instance work before triangles: bounding spheres, frustum culling, LOD selection.
#include <cstdint>
#include <vector>

#include "render/scene.hpp"
#include "render/view_projection.hpp"

namespace silva::render {

/// Value of an instance's LOD entry when the instance is not drawn.
inline constexpr uint32_t kCulled = 0xffffffffu;

/// A sphere in object space.
struct BoundingSphere {
  Vec3d center = Vec3d::Zero();  ///< Centre.
  double radius = -1.0;          ///< Radius; negative for an empty mesh.
};

/// Bounding sphere of every scene mesh (from MeshLods::bounds, or the LODs' positions when
/// those bounds are empty). Throws InputError for a mesh without LODs or with a null LOD.
void mesh_spheres(const Scene& scene, std::vector<BoundingSphere>& out);

/// Per instance: the LOD to draw (0 when `lod` is false), or kCulled when its bounding sphere
/// lies outside the view. Throws InputError for an instance naming a missing mesh.
void select_instances(const Scene& scene, const ViewProjection& view, const std::vector<BoundingSphere>& spheres,
                      bool lod, std::vector<uint32_t>& lod_out);

}  // namespace silva::render
