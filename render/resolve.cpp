#include "render/resolve.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "render/raster_conventions.hpp"
#include "core/surface_overlay.hpp"

namespace silva::render {

namespace {

/// The part a triangle belongs to (parts cover the index buffer in order).
const MeshPart& part_of(const Mesh& mesh, uint32_t triangle) {
  const uint32_t index = triangle * 3;
  auto it = std::upper_bound(mesh.parts.begin(), mesh.parts.end(), index,
                             [](uint32_t i, const MeshPart& p) { return i < p.first_index; });
  return *(it - 1);
}

/// Writes a pixel that saw nothing.
void write_miss(GBuffer& g, size_t i) {
  g.depth[i] = 0.0f;
  g.position[i] = Vec3f::Zero();
  g.normal[i] = Vec3f::Zero();
  g.uv[i] = Vec2f::Zero();
  g.role[i] = Role::Background;
  g.material[i] = Material::Ground;
  g.base_color[i] = 0;
  g.instance_id[i] = 0;
  g.variation[i] = 0;
  g.leaf[i] = 0;
  g.mask_texels[i] = 0.0f;
}

/// Mips without coarse levels: every footprint reads the mask itself.
const LeafMips kMaskItself;

/// World-space data of one (instance, triangle) pair, prepared once and reused by every pixel
/// of the frame's row block that sees it.
struct HitTriangle {
  uint32_t instance = kNoInstance, triangle = 0;  ///< Which triangle this is (kNoInstance: none yet).
  const Instance* inst = nullptr;                 ///< Its instance.
  const Mesh* mesh = nullptr;                     ///< The LOD drawn.
  const uint32_t* idx = nullptr;                  ///< Its three vertex indices.
  const MeshPart* part = nullptr;                 ///< Its part (role, material).
  Vec3d p[3];                                     ///< World-space vertices.
  Vec3d e1, e2;                                   ///< Edges p1 - p0 and p2 - p0.
  Vec3d s;                                        ///< Camera origin - p0 (Moller-Trumbore).
  Vec3d qvec;                                     ///< s x e1: constant over the triangle's pixels.
  double e2_dot_q = 0;                            ///< e2 . qvec (t = e2_dot_q / det).
  Mat3d cof;                                      ///< Normal transform (cofactor of the linear part).
  Eigen::Matrix<double, 3, 4> m;                  ///< The instance's object -> world transform.
  double mask_texels_per_metre = 0;               ///< Masked part: mask texels per metre of the triangle (isotropic).
  const AlphaMask* mips_of = nullptr;             ///< The mask `mips` belongs to (null: none looked up yet).
  const LeafMips* mips = nullptr;                 ///< Leaf mips of the part's mask (null without a mask).

  /// Prepares triangle `triangle` of `instance` drawn at LOD `lod`, seen from `origin` (the
  /// instance's transforms are kept when the slot held the same instance before).
  void prepare(const Scene& scene, const MaskCache& masks, uint32_t instance_index, uint32_t lod,
               uint32_t triangle_index, const Vec3d& origin) {
    if (instance_index != instance) {
      inst = &scene.instances[instance_index];
      m = inst->object_to_world.cast<double>();
      const Mat3d lin = m.leftCols<3>();
      cof.col(0) = lin.col(1).cross(lin.col(2));
      cof.col(1) = lin.col(2).cross(lin.col(0));
      cof.col(2) = lin.col(0).cross(lin.col(1));
      if (lin.determinant() < 0.0) cof = -cof;
    }
    instance = instance_index;
    triangle = triangle_index;
    mesh = scene.meshes[inst->mesh].lods[lod];
    idx = &mesh->indices[size_t(triangle_index) * 3];
    for (int k = 0; k < 3; ++k) p[k] = m.leftCols<3>() * mesh->positions[idx[k]].cast<double>() + m.col(3);
    e1 = p[1] - p[0];
    e2 = p[2] - p[0];
    s = origin - p[0];
    qvec = s.cross(e1);
    e2_dot_q = e2.dot(qvec);
    part = &part_of(*mesh, triangle_index);
    mask_texels_per_metre = part->mask && !mesh->uvs.empty() ? texel_density(*part->mask) : 0.0;
    if (part->mask.get() != mips_of) {  // the slot's last mask is most often this one
      mips_of = part->mask.get();
      mips = mips_of ? masks.leaf_mips(mips_of) : nullptr;
      if (mips_of && !mips) mips = &kMaskItself;  // a mask the cache lacks is read at level 0
    }
  }

  /// Mask texels per metre: the square root of the triangle's area in texels over its world area.
  double texel_density(const AlphaMask& mask) const {
    const Eigen::Vector2d texels(mask.width, mask.height), t0 = mesh->uvs[idx[0]].cast<double>();
    const Eigen::Vector2d a = (mesh->uvs[idx[1]].cast<double>() - t0).cwiseProduct(texels);
    const Eigen::Vector2d b = (mesh->uvs[idx[2]].cast<double>() - t0).cwiseProduct(texels);
    const double world = e1.cross(e2).norm();
    return world > 0.0 ? std::sqrt(std::abs(a.x() * b.y() - a.y() * b.x()) / world) : 0.0;
  }
};

/// Slots of the direct-mapped cache of prepared triangles (a foliage card's triangle is seen by
/// pixels of several rows; a quarter of a frame's hits change triangle from their left neighbour).
constexpr size_t kTriangleSlots = 256;

/// A thread's prepared triangles, indexed by a hash of (instance, triangle).
class TriangleCache {
 public:
  /// The prepared triangle `triangle` of `instance` (LOD `lod`), preparing it on a miss.
  const HitTriangle& get(const Scene& scene, const MaskCache& masks, uint32_t instance, uint32_t lod, uint32_t triangle,
                         const Vec3d& origin) {
    const uint32_t h = (instance * 0x9E3779B1u) ^ (triangle * 0x85EBCA77u);
    HitTriangle& slot = slots_[(h ^ (h >> 15)) % kTriangleSlots];
    if (slot.instance != instance || slot.triangle != triangle) slot.prepare(scene, masks, instance, lod, triangle, origin);
    return slot;
  }

 private:
  std::vector<HitTriangle> slots_ = std::vector<HitTriangle>(kTriangleSlots);
};

/// Re-intersects a pixel's centre ray with its triangle and writes the surface.
/// (ray_x, ray_y) is the pixel's camera-space ray (Camera::ray_x, ray_y).
void write_hit(const Camera& cam, const HitTriangle& h, double ray_x, double ray_y, GBuffer& g, size_t i) {
  const Vec3d* p = h.p;
  const Vec3d& e1 = h.e1;
  const Vec3d& e2 = h.e2;
  const Mesh& mesh = *h.mesh;
  const uint32_t* idx = h.idx;
  const Vec3d origin = cam.position();
  const Vec3d dir = cam.world_direction(ray_x, ray_y);  // camera z component 1: t is metric z
  const Vec3d pvec = dir.cross(e2);
  const double det = e1.dot(pvec);
  double b1 = 1.0 / 3.0, b2 = 1.0 / 3.0, t = 0.0;
  if (det != 0.0) {
    b1 = h.s.dot(pvec) / det;
    b2 = dir.dot(h.qvec) / det;
    t = h.e2_dot_q / det;
  }
  if (!(t > 0.0)) {  // ray parallel to the triangle's plane: fall back to the centroid's depth
    const Vec3d centroid = (p[0] + p[1] + p[2]) / 3.0;
    t = (cam.world_to_camera().block<1, 3>(2, 0) * centroid)(0) + cam.world_to_camera()(2, 3);
    b1 = b2 = 1.0 / 3.0;
  }
  const double b0 = 1.0 - b1 - b2;
  const Vec3d hit = origin + t * dir;
  // Normal: interpolated vertex normals through the inverse transpose (cofactor matrix).
  Vec3d n_obj = e1.cross(e2);  // fallback: geometric normal (already in world space)
  bool object_space = false;
  if (!mesh.normals.empty()) {
    n_obj = b0 * mesh.normals[idx[0]].cast<double>() + b1 * mesh.normals[idx[1]].cast<double>() +
            b2 * mesh.normals[idx[2]].cast<double>();
    object_space = true;
  }
  Vec3d n = object_space ? Vec3d(h.cof * n_obj) : n_obj;
  const double len = n.norm();
  n = len > 0.0 ? Vec3d(n / len) : Vec3d(-dir.normalized());
  if (n.dot(dir) > 0.0) n = -n;
  Vec2f uv = Vec2f::Zero();
  if (!mesh.uvs.empty()) {
    const Eigen::Vector2d w = b0 * mesh.uvs[idx[0]].cast<double>() + b1 * mesh.uvs[idx[1]].cast<double>() +
                              b2 * mesh.uvs[idx[2]].cast<double>();
    uv = w.cast<float>();
  }
  g.depth[i] = float(t);
  g.position[i] = hit.cast<float>();
  g.normal[i] = n.cast<float>();
  g.uv[i] = uv;
  g.role[i] = h.part->role;
  g.material[i] = h.part->material;
  if (h.part->overlay && uv.x() < kOverlayMargin + kOverlayRagged) {
    const float edge = overlay_edge(uv.x(), g.position[i]);
    if (edge < kOverlayMargin) g.material[i] = h.part->overlay->material;
    if (overlay_weight(edge) >= 0.5f) g.role[i] = h.part->overlay->role;
  }
  g.base_color[i] = h.part->base_color ? pack_srgb8(h.part->base_color->albedo(uv.x(), uv.y())) : 0;
  g.instance_id[i] = h.inst->instance_id;
  g.variation[i] = h.inst->variation;
  const AlphaMask* mask = h.part->mask.get();
  g.mask_texels[i] = float(h.mask_texels_per_metre * t / cam.fx);  // the pixel is t / fx metres wide there
  g.leaf[i] = mask ? h.mips->alpha(*mask, uv.x(), uv.y(), g.mask_texels[i]) : 0;
}

}  // namespace

void resolve_gbuffer(const Scene& scene, const Camera& camera, const VisibilityBuffer& vis,
                     std::span<const uint32_t> instance_lod, const MaskCache& masks, GBuffer& out) {
  if (out.width != vis.width || out.height != vis.height || out.depth.size() != vis.size())
    out.resize(vis.width, vis.height);
  std::vector<double> ray_x(size_t(vis.width));
  for (int u = 0; u < vis.width; ++u) ray_x[size_t(u)] = camera.ray_x(u);
  tbb::enumerable_thread_specific<TriangleCache> caches;
  tbb::parallel_for(tbb::blocked_range<int>(0, vis.height, 8), [&](const tbb::blocked_range<int>& rows) {
    TriangleCache& cache = caches.local();
    const HitTriangle* h = nullptr;
    const Vec3d origin = camera.position();
    for (int v = rows.begin(); v != rows.end(); ++v) {
      const double ray_y = camera.ray_y(v);
      for (int u = 0; u < vis.width; ++u) {
        const size_t i = size_t(v) * size_t(vis.width) + size_t(u);
        const uint32_t inst = vis.instance[i];
        if (inst == kNoInstance) {
          write_miss(out, i);
        } else {
          if (!h || inst != h->instance || vis.triangle[i] != h->triangle)
            h = &cache.get(scene, masks, inst, instance_lod[inst], vis.triangle[i], origin);
          write_hit(camera, *h, ray_x[size_t(u)], ray_y, out, i);
        }
      }
    }
  });
}

}  // namespace silva::render
