#pragma once
/// @file The visibility pass: tiles rasterised in parallel into per-pixel (depth, instance, triangle).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <tbb/cache_aligned_allocator.h>
#include <tbb/enumerable_thread_specific.h>

#include "render/bin.hpp"
#include "render/tile_raster.hpp"

namespace silva::render {

/// Per-pixel result of the visibility pass, row-major. Every pixel is written each pass.
struct VisibilityBuffer {
  int width = 0;                   ///< Pixels across.
  int height = 0;                  ///< Pixels down.
  /// A plane of per-pixel values, cache-line aligned so that whole tile rows stream to memory.
  template <class T>
  using Plane = std::vector<T, tbb::cache_aligned_allocator<T>>;
  Plane<float> depth;        ///< Reverse depth d of the winner (1/z or -z); 0 where no hit.
  Plane<uint32_t> instance;  ///< Scene instance index of the winner, kNoInstance where no hit.
  Plane<uint32_t> triangle;  ///< Triangle index within the instance's drawn LOD mesh.
  /// Sizes the planes for w x h (contents undefined until a pass writes them).
  void resize(int w, int h);
  /// Number of pixels.
  size_t size() const { return size_t(width) * size_t(height); }
};

/// Thread-local tile scratch, reused across tiles and frames.
using TileScratchSet = tbb::enumerable_thread_specific<TileScratch>;

/// Rasterises every tile of `grid` in parallel (TBB, the caller's arena) from the binned
/// triangles of all stores and writes the winners to `out` (already sized to the grid).
/// The result does not depend on the number of threads or the order of `stores`.
TileCounters rasterise_tiles(const TileGrid& grid, double depth_clear, std::span<const GeometryStore* const> stores,
                             TileScratchSet& scratch, VisibilityBuffer& out);

}  // namespace silva::render
