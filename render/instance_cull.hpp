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
/// those bounds are empty; radius -1 for a mesh without LODs, which no instance may draw), around
/// the shadow casters too when `shadow_casters`. Throws InputError for a null LOD.
void mesh_spheres(const Scene& scene, std::vector<BoundingSphere>& out, bool shadow_casters = false);

/// What culling decided for every scene instance in one view (indexed by instance).
struct InstanceSelection {
  std::vector<uint32_t> lod;     ///< LOD to draw (0 when LOD is off), or kCulled when outside the view.
  std::vector<uint8_t> inside;   ///< 1 when the sphere lies well inside every frustum plane (its
                                 ///< triangles skip the per-triangle frustum and clip tests), else 0.
  std::vector<double> nearness;  ///< Depth of the sphere's nearest point along the view (draw order key).
  std::vector<uint32_t> order;   ///< Drawn instances, nearest first by float(nearness), ties by index.
};

/// Culls and picks LODs of every instance by its bounding sphere, and orders the drawn ones
/// nearest first. With `shadow_casters`, a mesh's shadow caster (level lods.size()) replaces the
/// picked level when it has fewer triangles. Instances whose bounding sphere's radius is below
/// `min_radius` (metres) are culled. Throws InputError for an instance naming a missing mesh.
void select_instances(const Scene& scene, const ViewProjection& view, const std::vector<BoundingSphere>& spheres,
                      bool lod, InstanceSelection& out, bool shadow_casters = false, double min_radius = 0.0);

}  // namespace silva::render
