#include "render/resolve.hpp"

#include <algorithm>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "render/raster_conventions.hpp"
#include "render/resolve_lanes.hpp"
#include "render/surface_overlay.hpp"

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
}

/// Copies an Eigen 3-vector into a plain array.
void store3(double (&out)[3], const Vec3d& v) {
  for (int a = 0; a < 3; ++a) out[a] = v[a];
}

/// World-space data of one (instance, triangle) pair, prepared once and reused by every pixel
/// of the frame's row block that sees it.
struct HitTriangle {
  uint32_t instance = kNoInstance, triangle = 0;  ///< Which triangle this is (kNoInstance: none yet).
  const Instance* inst = nullptr;                 ///< Its instance.
  const MeshPart* part = nullptr;                 ///< Its part (role, material).
  Mat3d cof;                                      ///< Normal transform (cofactor of the linear part).
  Eigen::Matrix<double, 3, 4> m;                  ///< The instance's object -> world transform.
  ResolveTriangle lanes{};                        ///< What the resolve lanes read of it.

  /// Prepares triangle `triangle` of `instance` drawn at LOD `lod`, seen from `origin`, whose
  /// camera maps world to camera space by `world_to_camera` (the instance's transforms are kept
  /// when the slot held the same instance before).
  void prepare(const Scene& scene, uint32_t instance_index, uint32_t lod, uint32_t triangle_index,
               const Vec3d& origin, const Mat4d& world_to_camera) {
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
    const Mesh& mesh = *scene.meshes[inst->mesh].lods[lod];
    const uint32_t* idx = &mesh.indices[size_t(triangle_index) * 3];
    Vec3d p[3];
    for (int k = 0; k < 3; ++k) p[k] = m.leftCols<3>() * mesh.positions[idx[k]].cast<double>() + m.col(3);
    const Vec3d e1 = p[1] - p[0], e2 = p[2] - p[0], s = origin - p[0];
    const Vec3d qvec = s.cross(e1);
    const Vec3d centroid = (p[0] + p[1] + p[2]) / 3.0;
    store3(lanes.e1, e1);
    store3(lanes.e2, e2);
    store3(lanes.s, s);
    store3(lanes.qvec, qvec);
    lanes.e2_dot_q = e2.dot(qvec);
    lanes.fallback_t = (world_to_camera.block<1, 3>(2, 0) * centroid)(0) + world_to_camera(2, 3);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) lanes.cof[r][c] = cof(r, c);
    lanes.has_normals = mesh.normals.empty() ? 0.0 : 1.0;
    lanes.has_uvs = mesh.uvs.empty() ? 0.0 : 1.0;
    for (int k = 0; k < 3; ++k) {
      for (int a = 0; a < 3; ++a) lanes.normal[k][a] = mesh.normals.empty() ? 0.0 : double(mesh.normals[idx[k]][a]);
      for (int a = 0; a < 2; ++a) lanes.uv[k][a] = mesh.uvs.empty() ? 0.0 : double(mesh.uvs[idx[k]][a]);
    }
    store3(lanes.geometric, e1.cross(e2));
    part = &part_of(mesh, triangle_index);
  }
};

/// Slots of the direct-mapped cache of prepared triangles (a foliage card's triangle is seen by
/// pixels of several rows; a quarter of a frame's hits change triangle from their left neighbour).
constexpr size_t kTriangleSlots = 256;

/// A thread's prepared triangles, indexed by a hash of (instance, triangle).
class TriangleCache {
 public:
  /// The prepared triangle `triangle` of `instance` (LOD `lod`), preparing it on a miss.
  const HitTriangle& get(const Scene& scene, uint32_t instance, uint32_t lod, uint32_t triangle, const Vec3d& origin,
                         const Mat4d& world_to_camera) {
    const uint32_t h = (instance * 0x9E3779B1u) ^ (triangle * 0x85EBCA77u);
    HitTriangle& slot = slots_[(h ^ (h >> 15)) % kTriangleSlots];
    if (slot.instance != instance || slot.triangle != triangle)
      slot.prepare(scene, instance, lod, triangle, origin, world_to_camera);
    return slot;
  }

 private:
  std::vector<HitTriangle> slots_ = std::vector<HitTriangle>(kTriangleSlots);
};

/// What a pixel takes from its triangle's part and instance besides the lanes' geometry.
struct HitSource {
  const MeshPart* part = nullptr;  ///< Role, material, overlay, base colour.
  const Instance* inst = nullptr;  ///< Instance id and variation.
};

/// A thread's buffers for one row: its hit pixels, their triangles and what the lanes compute.
struct RowHits {
  std::vector<ResolveTriangle> triangles;  ///< One per run of pixels seeing the same triangle.
  std::vector<HitSource> sources;          ///< Alongside `triangles`.
  std::vector<int64_t> triangle;           ///< Per hit pixel: index into `triangles`.
  std::vector<double> ray_x;               ///< Per hit pixel: its ray's camera-space x / z.
  std::vector<uint32_t> column;            ///< Per hit pixel: u.
  std::vector<double> t, position[3], normal[3], uv[2];  ///< The lanes' results per hit pixel.

  /// Starts a new row.
  void clear() {
    triangles.clear();
    sources.clear();
    triangle.clear();
    ray_x.clear();
    column.clear();
  }

  /// Pads the per-pixel inputs to whole vectors and sizes the outputs alike.
  void pad() {
    const size_t lanes = resolve_lane_padding();
    const size_t padded = (column.size() + lanes - 1) / lanes * lanes;
    triangle.resize(padded, 0);
    ray_x.resize(padded, 0.0);
    for (std::vector<double>* v : {&t, &position[0], &position[1], &position[2], &normal[0], &normal[1], &normal[2],
                                   &uv[0], &uv[1]})
      v->resize(padded);
  }
};

/// Writes hit pixel k of `hits` (after the lanes ran) into pixel i of `g`.
void write_hit(const RowHits& hits, size_t k, GBuffer& g, size_t i) {
  const HitSource& src = hits.sources[size_t(hits.triangle[k])];
  const Vec2f uv(float(hits.uv[0][k]), float(hits.uv[1][k]));
  g.depth[i] = float(hits.t[k]);
  g.position[i] = Vec3f(float(hits.position[0][k]), float(hits.position[1][k]), float(hits.position[2][k]));
  g.normal[i] = Vec3f(float(hits.normal[0][k]), float(hits.normal[1][k]), float(hits.normal[2][k]));
  g.uv[i] = uv;
  g.role[i] = src.part->role;
  g.material[i] = src.part->material;
  if (src.part->overlay && uv.x() < kOverlayMargin + kOverlayRagged) {
    const float edge = overlay_edge(uv.x(), g.position[i]);
    if (edge < kOverlayMargin) g.material[i] = src.part->overlay->material;
    if (overlay_weight(edge) >= 0.5f) g.role[i] = src.part->overlay->role;
  }
  g.base_color[i] = src.part->base_color ? pack_srgb8(src.part->base_color->albedo(uv.x(), uv.y())) : 0;
  g.instance_id[i] = src.inst->instance_id;
  g.variation[i] = src.inst->variation;
}

}  // namespace

void resolve_gbuffer(const Scene& scene, const Camera& camera, const VisibilityBuffer& vis,
                     std::span<const uint32_t> instance_lod, GBuffer& out) {
  if (out.width != vis.width || out.height != vis.height || out.depth.size() != vis.size())
    out.resize(vis.width, vis.height);
  std::vector<double> ray_x(size_t(vis.width));
  for (int u = 0; u < vis.width; ++u) ray_x[size_t(u)] = camera.ray_x(u);
  const Mat4d world_to_camera = camera.world_to_camera();
  ResolveRow lanes_row;
  const Vec3d origin = camera.position();
  for (int a = 0; a < 3; ++a) {
    lanes_row.origin[a] = origin[a];
    for (int c = 0; c < 3; ++c) lanes_row.rotation[a][c] = camera.camera_to_world(a, c);
  }
  tbb::enumerable_thread_specific<TriangleCache> caches;
  tbb::enumerable_thread_specific<RowHits> rows_hits;
  tbb::parallel_for(tbb::blocked_range<int>(0, vis.height, 8), [&](const tbb::blocked_range<int>& rows) {
    TriangleCache& cache = caches.local();
    RowHits& hits = rows_hits.local();
    for (int v = rows.begin(); v != rows.end(); ++v) {
      hits.clear();
      const HitTriangle* h = nullptr;
      for (int u = 0; u < vis.width; ++u) {
        const size_t i = size_t(v) * size_t(vis.width) + size_t(u);
        const uint32_t inst = vis.instance[i];
        if (inst == kNoInstance) {
          write_miss(out, i);
          continue;
        }
        if (!h || inst != h->instance || vis.triangle[i] != h->triangle) {
          h = &cache.get(scene, inst, instance_lod[inst], vis.triangle[i], origin, world_to_camera);
          hits.triangles.push_back(h->lanes);
          hits.sources.push_back({h->part, h->inst});
        }
        hits.triangle.push_back(int64_t(hits.triangles.size() - 1));
        hits.ray_x.push_back(ray_x[size_t(u)]);
        hits.column.push_back(uint32_t(u));
      }
      if (hits.column.empty()) continue;
      const size_t count = hits.column.size();
      hits.pad();
      ResolveRow row = lanes_row;
      row.triangles = hits.triangles.data();
      row.triangle = hits.triangle.data();
      row.ray_x = hits.ray_x.data();
      row.ray_y = camera.ray_y(v);
      row.count = count;
      resolve_hits_lanes(row, {hits.t.data(),
                               {hits.position[0].data(), hits.position[1].data(), hits.position[2].data()},
                               {hits.normal[0].data(), hits.normal[1].data(), hits.normal[2].data()},
                               {hits.uv[0].data(), hits.uv[1].data()}});
      for (size_t k = 0; k < count; ++k) write_hit(hits, k, out, size_t(v) * size_t(vis.width) + hits.column[k]);
    }
  });
}

}  // namespace silva::render
