#include "render/bin.hpp"

#include <algorithm>

namespace silva::render {

namespace {

/// False when some edge is negative over the whole pixel rectangle (no sample inside).
bool may_cover(const RasterTri& t, int x0, int y0, int x1, int y1) {
  for (const EdgeFunction& e : t.edge)
    if (e.max_over(x0, y0, x1, y1) < 0.0) return false;
  return true;
}

}  // namespace

TileGrid TileGrid::make(int width, int height, int tile_size) {
  TileGrid g;
  g.width = width;
  g.height = height;
  g.tile_size = tile_size;
  g.tile_reciprocal = ((uint64_t(1) << 32) + uint64_t(tile_size) - 1) / uint64_t(tile_size);
  g.tiles_x = (width + tile_size - 1) / tile_size;
  g.tiles_y = (height + tile_size - 1) / tile_size;
  return g;
}

void GeometryStore::reset(int tile_count) {
  tris.clear();
  alphas.clear();
  if (bins.size() != size_t(tile_count)) bins.resize(size_t(tile_count));
  for (auto& b : bins) b.clear();
  counters = SetupCounters{};
  bin_entries = 0;
}

void GeometryStore::bin_across_tiles(uint32_t index, const TriBounds& b, const TileGrid& grid) {
  const RasterTri& t = tris[index];
  const int ts = grid.tile_size;
  const int tx0 = grid.tile_of(b.x0), tx1 = grid.tile_of(b.x1), ty0 = grid.tile_of(b.y0), ty1 = grid.tile_of(b.y1);
  for (int ty = ty0; ty <= ty1; ++ty) {
    for (int tx = tx0; tx <= tx1; ++tx) {
      const int x0 = std::max(b.x0, tx * ts), x1 = std::min(b.x1, tx * ts + ts - 1);
      const int y0 = std::max(b.y0, ty * ts), y1 = std::min(b.y1, ty * ts + ts - 1);
      if (may_cover(t, x0, y0, x1, y1)) add_entry(index, b.depth_max, tx, ty, x0, y0, x1, y1, grid);
    }
  }
}

}  // namespace silva::render
