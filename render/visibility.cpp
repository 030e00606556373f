#include "render/visibility.hpp"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include "hwy/cache_control.h"

#include "render/raster_conventions.hpp"

namespace silva::render {

namespace {

/// Copies a rasterised tile's winners into the visibility buffer; returns the pixels with one.
size_t write_tile(const TileJob& job, const TileScratch& s, VisibilityBuffer& out) {
  size_t covered = 0;
  for (int y = 0; y < job.h; ++y) {
    const size_t src = size_t(y) * size_t(job.stride);
    const size_t dst = size_t(job.y0 + y) * size_t(out.width) + size_t(job.x0);
    covered += split_winners(s.depth.data() + src, s.key.data() + src, size_t(job.w), out.depth.data() + dst,
                  out.instance.data() + dst, out.triangle.data() + dst);
  }
  hwy::FlushStream();  // split_winners' streamed stores are ordered before anything after
  return covered;
}

}  // namespace

void VisibilityBuffer::resize(int w, int h) {
  width = w;
  height = h;
  depth.resize(size());
  instance.resize(size());
  triangle.resize(size());
}

TileCounters rasterise_tiles(const TileGrid& grid, double depth_clear, std::span<const GeometryStore* const> stores,
                             TileScratchSet& scratch, VisibilityBuffer& out) {
  tbb::combinable<TileCounters> totals;
  tbb::parallel_for(tbb::blocked_range<int>(0, grid.count(), 1), [&](const tbb::blocked_range<int>& r) {
    TileScratch& s = scratch.local();
    TileCounters& counters = totals.local();
    for (int tile = r.begin(); tile != r.end(); ++tile) {
      TileJob job;
      job.x0 = (tile % grid.tiles_x) * grid.tile_size;
      job.y0 = (tile / grid.tiles_x) * grid.tile_size;
      job.w = std::min(grid.tile_size, grid.width - job.x0);
      job.h = std::min(grid.tile_size, grid.height - job.y0);
      job.stride = grid.tile_size;
      job.depth_clear = depth_clear;
      s.sources.clear();
      for (const GeometryStore* store : stores) {
        const auto& bin = store->bins[size_t(tile)];
        if (!bin.empty()) s.sources.push_back(TileSource{store->tris.data(), store->alphas.data(), bin.data(), bin.size()});
      }
      rasterise_tile(job, s.sources, s, counters);
      counters.covered += write_tile(job, s, out);
    }
  });
  TileCounters sum;
  totals.combine_each([&](const TileCounters& c) {
    sum.fragments += c.fragments;
    sum.writes += c.writes;
    sum.covered += c.covered;
  });
  return sum;
}

}  // namespace silva::render
