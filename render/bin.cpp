#include "render/bin.hpp"

#include <algorithm>

namespace silva::render {

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
    const int y0 = std::max(b.y0, ty * ts), y1 = std::min(b.y1, ty * ts + ts - 1);
    // An edge's largest value over a rectangle of pixels is its value at the corner its gradient
    // points to (x1 when dy <= 0, y1 when dx >= 0); here (c + b*y) at that row, as EdgeFunction::at.
    double row[3];
    for (int k = 0; k < 3; ++k) row[k] = t.edge[k].c + t.edge[k].b() * double(t.edge[k].dx >= 0 ? y1 : y0);
    bool found = false;
    for (int tx = tx0; tx <= tx1; ++tx) {
      const int x0 = std::max(b.x0, tx * ts), x1 = std::min(b.x1, tx * ts + ts - 1);
      bool may_cover = true;  // every edge's largest value over the tile's part >= 0
      for (int k = 0; k < 3; ++k) may_cover = may_cover && row[k] + t.edge[k].a() * double(t.edge[k].dy <= 0 ? x1 : x0) >= 0.0;
      if (may_cover) {
        add_entry(index, b.depth_max, tx, ty, x0, y0, x1, y1, grid);
        found = true;
      } else if (found) {
        // Along a row each edge's test passes on a prefix or a suffix of the tiles (its largest
        // value is monotone in x), so the tiles that pass all three are consecutive.
        break;
      }
    }
  }
}

}  // namespace silva::render
