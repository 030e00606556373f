#pragma once
/// @file The geometry pass: instance triangles -> view space -> set-up screen triangles -> bins.
#include <cstdint>
#include <span>
#include <vector>

#include <tbb/enumerable_thread_specific.h>

#include "render/mask_cache.hpp"
#include "render/bin.hpp"
#include "render/instance_cull.hpp"
#include "render/scene.hpp"
#include "render/triangle_setup.hpp"

namespace silva::render {

/// Largest number of triangles one geometry task processes.
inline constexpr uint32_t kTrianglesPerItem = 1024;

/// A run of one drawn instance's triangles, processed as one task.
struct DrawItem {
  uint32_t instance = 0;        ///< Scene instance index.
  uint32_t lod = 0;             ///< LOD drawn.
  uint32_t first_triangle = 0;  ///< First triangle of the run.
  uint32_t triangle_count = 0;  ///< Triangles in the run.
  bool inside_view = false;     ///< The instance lies inside the view (no per-triangle frustum/clip tests).
};

/// Geometry stores of a pass, one per chunk of consecutive draw items, in draw order; reused
/// across frames.
using GeometryStoreSet = std::vector<GeometryStore>;

/// Per-worker transformed vertices of the item being set up (scratch, reused across frames).
using VertexCacheSet = tbb::enumerable_thread_specific<VertexCache>;

/// Chunks the geometry pass cuts the items into per worker thread (load balance).
inline constexpr size_t kChunksPerThread = 8;

/// Splits the drawn instances, in selection.order (nearest first), into items of at most kTrianglesPerItem
/// triangles; returns the number of triangles submitted.
uint64_t build_draw_items(const Scene& scene, const InstanceSelection& selection, std::vector<DrawItem>& items);

/// Transforms, culls, clips, sets up and bins every item's triangles into `stores`, resized to
/// one store per chunk of consecutive items (kChunksPerThread per worker of the current arena, cut
/// at equal submitted triangle counts) and each reset for `grid`; chunks run in parallel, each in
/// item order, so reading the stores in order visits every tile's triangles in draw order for any
/// thread count. Vertices are transformed into the calling worker's cache of `caches`. Masked parts
/// take their bits from `masks` (updated for this scene). Throws InputError for a mesh whose
/// indices, normals or uvs do not match its positions.
void run_geometry_pass(const Scene& scene, const SetupView& view, std::span<const DrawItem> items, bool cull_back,
                       const MaskCache& masks, const TileGrid& grid, GeometryStoreSet& stores,
                       VertexCacheSet& caches);

}  // namespace silva::render
