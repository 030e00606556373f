#include "render/geometry_pass.hpp"

#include <algorithm>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include "core/error.hpp"
#include "render/item_placement.hpp"
#include "render/setup_lanes.hpp"
#include "render/vertex_lanes.hpp"

namespace silva::render {

namespace {

/// Object -> view transform of an instance, in double.
Eigen::Matrix<double, 3, 4> object_to_view(const Instance& inst, const ViewProjection& view) {
  Mat4d o2w = Mat4d::Identity();
  o2w.topRows<3>() = inst.object_to_world.cast<double>();
  return (view.world_to_view * o2w).topRows<3>();
}

/// Throws InputError unless the mesh's arrays agree with each other.
void check_mesh(const Mesh& mesh, uint32_t mesh_index) {
  const size_t n = mesh.positions.size();
  const auto fail = [&](const std::string& what) {
    throw InputError("render scene: mesh " + std::to_string(mesh_index) + ": " + what);
  };
  if (mesh.indices.size() % 3 != 0) fail("index count is not a multiple of 3");
  if (!mesh.uvs.empty() && mesh.uvs.size() != n) fail("uv count differs from the position count");
  if (!mesh.normals.empty() && mesh.normals.size() != n) fail("normal count differs from the position count");
  for (const MeshPart& p : mesh.parts) {
    if (p.first_index % 3 != 0 || p.index_count % 3 != 0 || size_t(p.first_index) + p.index_count > mesh.indices.size())
      fail("a part's index range is not whole triangles inside the index buffer");
    if (p.mask && mesh.uvs.empty()) fail("an alpha-masked part needs uvs");
  }
}

/// Triangles placed at once within an item of an instance that straddles the view.
constexpr uint32_t kPlacementRun = 128;

/// The vertices an item's triangles use: indices [first, first + count).
struct VertexRange {
  uint32_t first = 0;  ///< Smallest index.
  uint32_t count = 0;  ///< Largest - smallest + 1; 0 when not worth a whole-range pass.
};

/// The index range of triangles [t_begin, t_end), or count 0 when the range is empty, holds an
/// index past the vertices (the triangle loop then reports it) or is sparse (mostly unused).
VertexRange item_vertex_range(const Mesh& mesh, uint32_t t_begin, uint32_t t_end) {
  if (t_begin == t_end) return {};
  uint32_t lo = UINT32_MAX, hi = 0;  // a plain loop: the compiler vectorises it (minmax_element it does not)
  for (size_t i = size_t(t_begin) * 3; i < size_t(t_end) * 3; ++i) {
    lo = std::min(lo, mesh.indices[i]);
    hi = std::max(hi, mesh.indices[i]);
  }
  if (hi >= mesh.positions.size()) return {};
  const uint32_t count = hi - lo + 1;
  if (count > 4 * (t_end - t_begin)) return {};
  return {lo, count};
}

/// What the triangle runs of one item share.
struct ItemContext {
  const Scene& scene;                     ///< The scene.
  const SetupView& sv;                    ///< The view.
  const DrawItem& item;                   ///< The item.
  const Mesh& mesh;                       ///< Its LOD's mesh.
  Eigen::Matrix<double, 3, 4> m;          ///< Object -> view.
  bool cull_back;                         ///< Back-face culling on for single-sided parts.
  const MaskCache& masks;                 ///< Opacity bits of the masks.
  const TileGrid& grid;                   ///< Tiles to bin into.
  GeometryStore& store;                   ///< Output.
  VertexCache& vertices;                  ///< The worker's transformed vertices of the item.
};

/// Sets up and bins triangles [t_begin, t_end) of the item, whose vertices `range` covers and
/// lie where `place` says (never Outside).
void process_run(const ItemContext& c, uint32_t t_begin, uint32_t t_end, VertexRange range, Placement place) {
  const Mesh& mesh = c.mesh;
  GeometryStore& store = c.store;
  const size_t vertex_count = mesh.positions.size();
  // No triangle needing clipping: set up on SIMD lanes (the frustum test on the lanes when the run
  // crosses a frustum plane), the used vertices transformed and projected at once (the same bits
  // as one by one).
  const bool lanes = (place == Placement::Inside || place == Placement::Unclipped) && c.sv.view.perspective &&
                     range.count > 0;
  if (lanes)
    project_vertices(c.m, c.sv.view, mesh.positions.data() + range.first, range.count,
                     c.vertices.fill(range.first, range.count));
  TriangleInput in;
  in.inside_view = place == Placement::Inside;
  TriBounds bounds[kMaxSetupTriangles];
  for (const MeshPart& part : mesh.parts) {
    const uint32_t p_begin = std::max(t_begin, part.first_index / 3);
    const uint32_t p_end = std::min(t_end, (part.first_index + part.index_count) / 3);
    in.mask = part.mask ? c.masks.find(part.mask.get()) : nullptr;
    in.cull_back = c.cull_back && !part.double_sided;
    if (lanes && p_begin < p_end) {
      setup_triangles_lanes(c.sv,
                            LaneTriangles{mesh.indices.data(), p_begin, p_end - p_begin, c.vertices.slots.data(),
                                          mesh.uvs.data(), in.mask, in.cull_back, uint64_t(c.item.instance) << 32,
                                          place == Placement::Unclipped},
                            c.grid, store);
      continue;
    }
    for (uint32_t t = p_begin; t < p_end; ++t) {
      for (int k = 0; k < 3; ++k) {
        const uint32_t v = mesh.indices[size_t(t) * 3 + size_t(k)];
        if (v >= vertex_count)
          throw InputError("render scene: mesh " + std::to_string(c.scene.instances[c.item.instance].mesh) +
                           " has index " + std::to_string(v) + " but only " + std::to_string(vertex_count) +
                           " vertices");
        in.v[k] = &c.vertices.get(v, [&] { return to_view(c.m, mesh.positions[v]); });
        if (in.mask) in.uv[k] = &mesh.uvs[v];
      }
      in.key = (uint64_t(c.item.instance) << 32) | t;
      const size_t first = store.tris.size();
      const int emitted = setup_triangle(c.sv, in, store.tris, store.alphas, bounds, store.counters);
      for (int k = 0; k < emitted; ++k) store.bin(uint32_t(first + size_t(k)), bounds[k], c.grid);
    }
  }
}

/// Sets up and bins the triangles of one item into `store`, transforming its vertices into the
/// worker's `vertices`. An item of an instance that straddles the view is placed run by run
/// (kPlacementRun triangles): runs wholly outside are dropped (each of their triangles would fail
/// the same frustum plane), runs that need no clipping go to the SIMD setup.
void process_item(const Scene& scene, const SetupView& sv, const DrawItem& item, bool cull_back,
                  const MaskCache& masks, const TileGrid& grid, GeometryStore& store, VertexCache& vertices) {
  const Instance& inst = scene.instances[item.instance];
  const ItemContext c{scene, sv, item, scene.meshes[inst.mesh].level(item.lod), object_to_view(inst, sv.view),
                      cull_back, masks, grid, store, vertices};
  const uint32_t t_begin = item.first_triangle, t_end = item.first_triangle + item.triangle_count;
  c.vertices.begin_item(c.mesh.positions.size());
  if (item.inside_view) {
    process_run(c, t_begin, t_end, item_vertex_range(c.mesh, t_begin, t_end), Placement::Inside);
    return;
  }
  for (uint32_t r = t_begin; r < t_end; r += kPlacementRun) {
    const uint32_t r_end = std::min(t_end, r + kPlacementRun);
    const VertexRange range = item_vertex_range(c.mesh, r, r_end);
    const Placement place = range.count > 0
                                ? place_points({c.mesh.positions.data() + range.first, range.count}, c.m, sv)
                                : Placement::Straddles;
    if (place != Placement::Outside) process_run(c, r, r_end, range, place);
  }
}

/// Boundaries of at most `chunks` runs of consecutive items with about equal triangle counts:
/// run c is items [cuts[c], cuts[c + 1]); no run is empty (one run, empty, when there are no items).
std::vector<size_t> chunk_cuts(std::span<const DrawItem> items, size_t chunks) {
  uint64_t total = 0;
  for (const DrawItem& item : items) total += item.triangle_count;
  std::vector<size_t> cuts{0};
  uint64_t done = 0;
  for (size_t i = 0; i < items.size(); ++i) {
    done += items[i].triangle_count;
    // Cut after item i once the run reaches its share of the triangles (total * k / chunks).
    if (i + 1 < items.size() && done * chunks >= total * cuts.size()) cuts.push_back(i + 1);
  }
  cuts.push_back(items.size());
  return cuts;
}

}  // namespace

uint64_t build_draw_items(const Scene& scene, const InstanceSelection& selection, std::vector<DrawItem>& items) {
  items.clear();
  // Front to back (selection.order), so the early depth test rejects more; the result never
  // depends on this order.
  uint64_t triangles = 0;
  for (const uint32_t i : selection.order) {
    const Mesh& mesh = scene.meshes[scene.instances[i].mesh].level(selection.lod[i]);
    const uint32_t n = uint32_t(mesh.triangle_count());
    triangles += n;
    for (uint32_t first = 0; first < n; first += kTrianglesPerItem)
      items.push_back(
          DrawItem{i, selection.lod[i], first, std::min(kTrianglesPerItem, n - first), selection.inside[i] != 0});
  }
  return triangles;
}

void run_geometry_pass(const Scene& scene, const SetupView& view, std::span<const DrawItem> items, bool cull_back,
                       const MaskCache& masks, const TileGrid& grid, GeometryStoreSet& stores,
                       VertexCacheSet& caches) {
  for (uint32_t i = 0; i < scene.meshes.size(); ++i) {
    for (const Mesh* lod : scene.meshes[i].lods) check_mesh(*lod, i);
    if (scene.meshes[i].shadow_caster) check_mesh(*scene.meshes[i].shadow_caster, i);
  }
  const std::vector<size_t> cuts = chunk_cuts(items, size_t(tbb::this_task_arena::max_concurrency()) * kChunksPerThread);
  stores.resize(cuts.size() - 1);
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, stores.size(), 1),
      [&](const tbb::blocked_range<size_t>& r) {
        for (size_t c = r.begin(); c != r.end(); ++c) {
          GeometryStore& store = stores[c];
          VertexCache& vertices = caches.local();
          store.reset(grid.count());
          for (size_t i = cuts[c]; i != cuts[c + 1]; ++i)
            process_item(scene, view, items[i], cull_back, masks, grid, store, vertices);
        }
      },
      tbb::simple_partitioner());
}

}  // namespace silva::render
