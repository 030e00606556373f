#include "render/resolve.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "render/hit_geometry.hpp"
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
  HitGeometry geo;                                ///< What its pixels' hit geometry reads.
  Eigen::Matrix<double, 3, 4> m;                  ///< The instance's object -> world transform.
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
      geo.cof.col(0) = lin.col(1).cross(lin.col(2));
      geo.cof.col(1) = lin.col(2).cross(lin.col(0));
      geo.cof.col(2) = lin.col(0).cross(lin.col(1));
      if (lin.determinant() < 0.0) geo.cof = -geo.cof;
    }
    instance = instance_index;
    triangle = triangle_index;
    mesh = scene.meshes[inst->mesh].lods[lod];
    idx = &mesh->indices[size_t(triangle_index) * 3];
    const auto corner = [&](int k) -> Vec3d { return m.leftCols<3>() * mesh->positions[idx[k]].cast<double>() + m.col(3); };
    geo.place(corner(0), corner(1), corner(2), origin);
    geo.has_normals = !mesh->normals.empty();
    geo.has_uvs = !mesh->uvs.empty();
    for (int k = 0; k < 3; ++k) {
      if (geo.has_normals) geo.corner_normal[k] = mesh->normals[idx[k]].cast<double>();
      if (geo.has_uvs) geo.corner_uv[k] = mesh->uvs[idx[k]].cast<double>();
    }
    part = &part_of(*mesh, triangle_index);
    geo.mask_texels_per_metre = part->mask && geo.has_uvs ? texel_density(*part->mask) : 0.0;
    if (part->mask.get() != mips_of) {  // the slot's last mask is most often this one
      mips_of = part->mask.get();
      mips = mips_of ? masks.leaf_mips(mips_of) : nullptr;
      if (mips_of && !mips) mips = &kMaskItself;  // a mask the cache lacks is read at level 0
    }
  }

  /// Mask texels per metre: the square root of the triangle's area in texels over its world area.
  double texel_density(const AlphaMask& mask) const {
    const Eigen::Vector2d texels(mask.width, mask.height), t0 = geo.corner_uv[0];
    const Eigen::Vector2d a = (geo.corner_uv[1] - t0).cwiseProduct(texels);
    const Eigen::Vector2d b = (geo.corner_uv[2] - t0).cwiseProduct(texels);
    const double world = geo.e1.cross(geo.e2).norm();
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

/// Writes a hit pixel's geometry.
void write_geometry(const PixelHit& hit, GBuffer& g, size_t i) {
  g.depth[i] = hit.depth;
  g.position[i] = hit.position;
  g.normal[i] = hit.normal;
  g.uv[i] = hit.uv;
  g.mask_texels[i] = hit.mask_texels;
}

/// Writes what a hit pixel takes from its triangle's part and instance, after its geometry: role and
/// material (or the overlay's), base colour, instance id and variation, and the leaf alpha.
void write_labels(const HitTriangle& h, GBuffer& g, size_t i) {
  const Vec2f& uv = g.uv[i];
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
  g.leaf[i] = mask ? h.mips->alpha(*mask, uv.x(), uv.y(), g.mask_texels[i]) : 0;
}

/// Shortest run of pixels whose geometry is computed on SIMD lanes (shorter ones: one pixel at a time,
/// which gives the same bits and is faster there).
constexpr size_t kLaneRunMin = 4;

/// Writes pixels [i, i + count) (count <= kHitRunMax) of a row, all seeing h: their geometry (on SIMD
/// lanes for runs of kLaneRunMin or more, a pixel taking a fallback one at a time), then their labels.
void write_run(const Camera& cam, const HitTriangle& h, const double* ray_x, double ray_y, GBuffer& g, size_t i,
               size_t count) {
  const uint64_t fallback =
      count < kLaneRunMin ? ~uint64_t(0)
                          : hit_geometry_run(cam, h.geo, ray_x, ray_y, count, &g.depth[i], &g.position[i], &g.normal[i],
                                             &g.uv[i], &g.mask_texels[i]);
  for (size_t k = 0; k < count; ++k) {
    if ((fallback >> k) & 1) write_geometry(hit_geometry(cam, h.geo, ray_x[k], ray_y), g, i + k);
    write_labels(h, g, i + k);
  }
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
      const size_t row = size_t(v) * size_t(vis.width);
      for (size_t u = 0; u < size_t(vis.width);) {
        const uint32_t inst = vis.instance[row + u], tri = vis.triangle[row + u];
        if (inst == kNoInstance) {
          write_miss(out, row + u++);
          continue;
        }
        size_t end = u + 1;  // the run of pixels that see the same triangle
        while (end < size_t(vis.width) && end - u < kHitRunMax && vis.instance[row + end] == inst &&
               vis.triangle[row + end] == tri)
          ++end;
        if (!h || inst != h->instance || tri != h->triangle)
          h = &cache.get(scene, masks, inst, instance_lod[inst], tri, origin);
        write_run(camera, *h, &ray_x[u], ray_y, out, row + u, end - u);
        u = end;
      }
    }
  });
}

}  // namespace silva::render
