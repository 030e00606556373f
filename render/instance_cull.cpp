#include "render/instance_cull.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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

/// Fills sel.order: the drawn instances sorted by float(nearness), ties by index. An LSD radix
/// sort of the ordered float bits, 8 bits a pass, each pass stable, over the instances listed in
/// index order (so ties keep it): linear in the instance count, the same for any thread count.
void draw_order(InstanceSelection& sel) {
  std::vector<uint32_t> index, key;
  for (uint32_t i = 0; i < uint32_t(sel.lod.size()); ++i)
    if (sel.lod[i] != kCulled) {
      index.push_back(i);
      key.push_back(ordered_bits(float(sel.nearness[i])));
    }
  std::vector<uint32_t> index_out(index.size()), key_out(key.size());
  for (int shift = 0; shift < 32; shift += 8) {
    size_t start[257] = {};  // start[d + 1] counts digit d, then start[d] is where digit d goes
    for (const uint32_t k : key) ++start[((k >> shift) & 255u) + 1];
    if (std::find(start + 1, start + 257, key.size()) != start + 257) continue;  // one digit: no move
    for (int d = 0; d < 256; ++d) start[d + 1] += start[d];
    for (size_t k = 0; k < key.size(); ++k) {
      const size_t to = start[(key[k] >> shift) & 255u]++;
      index_out[to] = index[k];
      key_out[to] = key[k];
    }
    index.swap(index_out);
    key.swap(key_out);
  }
  sel.order = std::move(index);
}

}  // namespace

void mesh_spheres(const Scene& scene, std::vector<BoundingSphere>& out, bool shadow_casters) {
  out.resize(scene.meshes.size());
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    const MeshLods& m = scene.meshes[i];
    for (const Mesh* lod : m.lods)
      if (!lod) throw InputError("render scene: mesh " + std::to_string(i) + " has a null LOD pointer");
    if (m.shadow_caster && m.lods.empty())
      throw InputError("render scene: mesh " + std::to_string(i) + " has a shadow caster but no LOD");
  }
  tbb::parallel_for(size_t(0), scene.meshes.size(), [&](size_t i) {
    const MeshLods& m = scene.meshes[i];
    AABB b = m.bounds;
    if (b.empty())
      for (const Mesh* lod : m.lods) b.extend(lod->bounds());
    if (shadow_casters && m.shadow_caster) b.extend(m.shadow_bounds.empty() ? m.shadow_caster->bounds() : m.shadow_bounds);
    BoundingSphere s;
    if (!b.empty()) {
      s.center = b.center().cast<double>();
      s.radius = 0.5 * b.size().cast<double>().norm();
    }
    out[i] = s;
  });
}

void select_instances(const Scene& scene, const ViewProjection& view, const std::vector<BoundingSphere>& spheres,
                      bool lod, InstanceSelection& out, bool shadow_casters, double min_radius) {
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    const uint32_t mesh = scene.instances[i].mesh;
    if (mesh >= scene.meshes.size())
      throw InputError("render scene: instance " + std::to_string(i) + " names mesh " + std::to_string(mesh) +
                       ", but the scene has " + std::to_string(scene.meshes.size()) + " meshes");
    if (scene.meshes[mesh].lods.empty())
      throw InputError("render scene: instance " + std::to_string(i) + " draws mesh " + std::to_string(mesh) +
                       ", which has no LOD (needs lods[0])");
  }
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
      // The longest column's length: one square root of the largest squared length (the same value,
      // as the square root is monotone and correctly rounded).
      const double scale = std::sqrt(m.leftCols<3>().colwise().squaredNorm().maxCoeff());
      const double r_world = s.radius * scale;
      const Vec3d c = view.world_to_view.topLeftCorner<3, 3>() * world_center + view.world_to_view.block<3, 1>(0, 3);
      if (s.radius < 0.0 || r_world < min_radius || !c.allFinite() || frustum.outside(c, r_world)) {
        out.lod[i] = kCulled;
        out.inside[i] = 0;
        out.nearness[i] = 0.0;
        continue;
      }
      out.inside[i] = frustum.inside(c, r_world) ? 1 : 0;
      const double distance = c.norm();
      out.nearness[i] = (view.perspective ? distance : c.z()) - r_world;
      const MeshLods& mesh = scene.meshes[inst.mesh];
      out.lod[i] = lod ? lod_for_size(mesh, view.screen_size(r_world, distance)) : 0u;
      if (shadow_casters && mesh.shadow_caster &&
          mesh.shadow_caster->triangle_count() < mesh.lods[out.lod[i]]->triangle_count())
        out.lod[i] = uint32_t(mesh.lods.size());
    }
  });
  draw_order(out);
}

}  // namespace silva::render
