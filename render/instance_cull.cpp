#include "render/instance_cull.hpp"

#include <bit>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "core/error.hpp"

namespace silva::render {

namespace {

/// Relative and absolute slack of the inside test, far above the rounding of float mesh bounds.
constexpr double kInsideMargin = 1e-4;

/// Picks the LOD for a projected size: the largest k with size < thresholds[k-1].
uint32_t lod_for_size(const MeshLods& m, double size) {
  uint32_t k = 0;
  const size_t levels = std::min(m.lods.size() - 1, m.lod_screen_sizes.size());
  for (size_t i = 0; i < levels; ++i)
    if (size < double(m.lod_screen_sizes[i])) k = uint32_t(i + 1);
  return k;
}

/// The view's frustum planes with their normals' lengths, computed once per pass.
struct FrustumTests {
  Vec4d planes[6];  ///< Plane k: n.p + w >= 0 inside.
  double len[6];    ///< |n| of plane k.
  int count = 0;    ///< Planes in use.

  explicit FrustumTests(const ViewProjection& view) : count(view.frustum_planes(planes)) {
    for (int k = 0; k < count; ++k) len[k] = planes[k].head<3>().norm();
  }

  /// True when the view-space sphere lies entirely outside one of the planes.
  bool outside(const Vec3d& c, double r) const {
    for (int k = 0; k < count; ++k)
      if (len[k] > 0.0 && (planes[k].head<3>().dot(c) + planes[k].w()) < -r * len[k]) return true;
    return false;
  }

  /// True when the view-space sphere lies inside every plane with a margin, so none of its
  /// triangles can be rejected by or need clipping against a plane (the per-triangle tests can go).
  bool inside(const Vec3d& c, double r) const {
    const double margin = r * (1.0 + kInsideMargin) + kInsideMargin;
    for (int k = 0; k < count; ++k)
      if (!(planes[k].head<3>().dot(c) + planes[k].w() > margin * len[k])) return false;
    return true;
  }
};

/// Bits of f whose unsigned order is the numeric order of finite floats.
uint32_t ordered_bits(float f) {
  const uint32_t u = std::bit_cast<uint32_t>(f);
  return (u >> 31) != 0 ? ~u : u | 0x80000000u;
}

/// Fills sel.order: the drawn instances sorted by (float(nearness), index) as one 64-bit key each
/// (a total order, so the parallel sort's result does not depend on the thread count).
void draw_order(InstanceSelection& sel) {
  std::vector<uint64_t> keys;
  for (uint32_t i = 0; i < uint32_t(sel.lod.size()); ++i)
    if (sel.lod[i] != kCulled) keys.push_back(uint64_t(ordered_bits(float(sel.nearness[i]))) << 32 | i);
  tbb::parallel_sort(keys.begin(), keys.end());
  sel.order.resize(keys.size());
  for (size_t k = 0; k < keys.size(); ++k) sel.order[k] = uint32_t(keys[k]);
}

}  // namespace

void mesh_spheres(const Scene& scene, std::vector<BoundingSphere>& out) {
  out.resize(scene.meshes.size());
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    const MeshLods& m = scene.meshes[i];
    if (m.lods.empty()) throw InputError("render scene: mesh " + std::to_string(i) + " has no LOD (needs lods[0])");
    for (const Mesh* lod : m.lods)
      if (!lod) throw InputError("render scene: mesh " + std::to_string(i) + " has a null LOD pointer");
  }
  tbb::parallel_for(size_t(0), scene.meshes.size(), [&](size_t i) {
    const MeshLods& m = scene.meshes[i];
    AABB b = m.bounds;
    if (b.empty())
      for (const Mesh* lod : m.lods) b.extend(lod->bounds());
    BoundingSphere s;
    if (!b.empty()) {
      s.center = b.center().cast<double>();
      s.radius = 0.5 * b.size().cast<double>().norm();
    }
    out[i] = s;
  });
}

void select_instances(const Scene& scene, const ViewProjection& view, const std::vector<BoundingSphere>& spheres,
                      bool lod, InstanceSelection& out) {
  for (size_t i = 0; i < scene.instances.size(); ++i)
    if (scene.instances[i].mesh >= scene.meshes.size())
      throw InputError("render scene: instance " + std::to_string(i) + " names mesh " +
                       std::to_string(scene.instances[i].mesh) + ", but the scene has " +
                       std::to_string(scene.meshes.size()) + " meshes");
  const FrustumTests frustum(view);
  out.lod.resize(scene.instances.size());
  out.inside.resize(scene.instances.size());
  out.nearness.resize(scene.instances.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, scene.instances.size(), 256), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i != r.end(); ++i) {
      const Instance& inst = scene.instances[i];
      const BoundingSphere& s = spheres[inst.mesh];
      const Eigen::Matrix<double, 3, 4> m = inst.object_to_world.cast<double>();
      const Vec3d world_center = m.leftCols<3>() * s.center + m.col(3);
      const double scale = m.leftCols<3>().colwise().norm().maxCoeff();
      const double r_world = s.radius * scale;
      const Vec3d c = view.world_to_view.topLeftCorner<3, 3>() * world_center + view.world_to_view.block<3, 1>(0, 3);
      if (s.radius < 0.0 || !c.allFinite() || frustum.outside(c, r_world)) {
        out.lod[i] = kCulled;
        out.inside[i] = 0;
        out.nearness[i] = 0.0;
        continue;
      }
      out.inside[i] = frustum.inside(c, r_world) ? 1 : 0;
      out.nearness[i] = (view.perspective ? c.norm() : c.z()) - r_world;
      out.lod[i] = lod ? lod_for_size(scene.meshes[inst.mesh], view.screen_size(r_world, c.norm())) : 0u;
    }
  });
  draw_order(out);
}

}  // namespace silva::render
