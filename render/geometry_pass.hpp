#pragma once
/// @file The geometry pass: instance triangles -> view space -> set-up screen triangles -> bins.
#include <cstdint>
#include <span>
#include <vector>

#include <tbb/enumerable_thread_specific.h>

#include "render/alpha_bits.hpp"
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

/// Thread-local geometry stores, reused across frames.
using GeometryStoreSet = tbb::enumerable_thread_specific<GeometryStore>;

/// Splits every drawn instance (lod != kCulled), nearest first, into items of at most kTrianglesPerItem
/// triangles; returns the number of triangles submitted.
uint64_t build_draw_items(const Scene& scene, const InstanceSelection& selection, std::vector<DrawItem>& items);

/// Transforms, culls, clips, sets up and bins every item's triangles in parallel into the
/// calling threads' stores (each reset for `grid` first); masked parts take their bits from
/// `masks` (updated for this scene). Throws InputError for a mesh whose indices, normals or uvs
/// do not match its positions.
void run_geometry_pass(const Scene& scene, const SetupView& view, std::span<const DrawItem> items, bool cull_back,
                       const AlphaBitsCache& masks, const TileGrid& grid, GeometryStoreSet& stores);

}  // namespace silva::render
