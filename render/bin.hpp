#pragma once
/// @file Binning: screen tiles and, per run of draw items, the lists of triangles touching each tile.
#include <cstdint>
#include <vector>

#include "render/raster_triangle.hpp"
#include "render/triangle_setup.hpp"

namespace silva::render {

/// The screen cut into square tiles, row-major.
struct TileGrid {
  int width = 0;      ///< Image width in pixels.
  int height = 0;     ///< Image height in pixels.
  int tile_size = 128; ///< Tile side in pixels.
  int tiles_x = 0;    ///< Tiles across.
  int tiles_y = 0;    ///< Tiles down.
  uint64_t tile_reciprocal = 0;  ///< ceil(2^32 / tile_size): tile_of's multiplier.
  /// Grid covering a width x height image with tile_size tiles (tile_size in 1..256).
  static TileGrid make(int width, int height, int tile_size);
  /// Tile column (or row) of pixel column (or row) p in [0, 2^16): p / tile_size by a multiply
  /// and a shift, exact in that range (the error term p * e / 2^32 < 2^-16 stays below 1/tile_size).
  int tile_of(int p) const { return int((uint64_t(uint32_t(p)) * tile_reciprocal) >> 32); }
  /// Number of tiles.
  int count() const { return tiles_x * tiles_y; }
};

/// One run of draw items' set-up triangles and, per tile, entries of those that touch it.
/// Keeps its capacity from frame to frame.
struct GeometryStore {
  std::vector<RasterTri> tris;              ///< Set-up screen triangles.
  std::vector<AlphaAttrib> alphas;          ///< Alpha-test data referenced by tris.
  std::vector<std::vector<BinEntry>> bins;  ///< Per tile: the triangles that may cover its samples.
  SetupCounters counters;                   ///< Front-end counters.
  uint64_t bin_entries = 0;                 ///< (triangle, tile) pairs added.
  /// Empties the store for a new pass over `tile_count` tiles (keeps capacity).
  void reset(int tile_count);
  /// Adds tris[index] (with its bounds) to the bins of every tile whose samples it may cover.
  void bin(uint32_t index, const TriBounds& bounds, const TileGrid& grid) {
    const int tx = grid.tile_of(bounds.x0), ty = grid.tile_of(bounds.y0);
    if (tx != grid.tile_of(bounds.x1) || ty != grid.tile_of(bounds.y1)) return bin_across_tiles(index, bounds, grid);
    add_entry(index, bounds.depth_max, tx, ty, bounds.x0, bounds.y0, bounds.x1, bounds.y1, grid);
  }

 private:
  /// bin() for a triangle whose bounds span several tiles: each tile where every edge is >= 0
  /// somewhere on the part of the tile inside the bounds (at the corner its gradient points to).
  void bin_across_tiles(uint32_t index, const TriBounds& bounds, const TileGrid& grid);
  /// Appends tris[index] to tile (tx, ty)'s bin with candidate pixels [x0, x1] x [y0, y1] (image
  /// coordinates inside that tile).
  void add_entry(uint32_t index, double depth_max, int tx, int ty, int x0, int y0, int x1, int y1, const TileGrid& grid) {
    const int ox = tx * grid.tile_size, oy = ty * grid.tile_size;
    bins[size_t(ty) * size_t(grid.tiles_x) + size_t(tx)].push_back(
        BinEntry{depth_max, index, uint8_t(x0 - ox), uint8_t(y0 - oy), uint8_t(x1 - ox), uint8_t(y1 - oy)});
    ++bin_entries;
  }
};

}  // namespace silva::render
