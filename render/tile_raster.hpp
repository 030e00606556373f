#pragma once
/// @file The tile rasteriser: edge functions and depth test on Highway SIMD lanes, one tile at a time.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "render/raster_triangle.hpp"

namespace silva::render {

/// The triangles one geometry store (run of draw items) binned to a tile.
struct TileSource {
  const RasterTri* tris = nullptr;      ///< The store's triangles.
  const AlphaAttrib* alphas = nullptr;  ///< The store's alpha data.
  const BinEntry* entries = nullptr;    ///< The store's bin of this tile (entries index tris).
  size_t count = 0;                     ///< Number of entries.
};

/// Where a tile lies and how it starts.
struct TileJob {
  int x0 = 0, y0 = 0;        ///< Image position of the tile's first pixel.
  int w = 0, h = 0;          ///< Tile extent (clipped to the image).
  int stride = 64;           ///< Row stride of the scratch planes (the tile size, a multiple of 8).
  double depth_clear = 0.0;  ///< Starting reverse depth of every pixel.
};

/// Per-worker tile planes, reused across tiles and frames (no allocation per tile once grown).
struct TileScratch {
  std::vector<double> depth;       ///< Winning reverse depth per pixel (row stride TileJob::stride).
  std::vector<uint64_t> key;       ///< Winning key per pixel, kNoKey when empty.
  std::vector<double> block_min;   ///< Minimum stored depth per 8x8 block.
  std::vector<TileSource> sources; ///< Sources of the current tile (filled by the caller).
};

/// Counters of the tile rasteriser.
struct TileCounters {
  uint64_t fragments = 0;  ///< Sample centres found inside a triangle.
  uint64_t writes = 0;     ///< Depth/key writes (overdraw included).
  uint64_t covered = 0;    ///< Pixels with a winner once their tile is done.
};

/// Rasterises every triangle of `sources` into the tile; the winners are left in scratch.depth
/// and scratch.key. Runs on the best Highway target the CPU supports (dynamic dispatch).
void rasterise_tile(const TileJob& job, std::span<const TileSource> sources, TileScratch& scratch,
                    TileCounters& counters);

/// Splits the winners of n pixels of a tile row into the visibility buffer's planes: reverse
/// depth as float (0 where nothing won), instance = key >> 32 (kNoInstance where nothing won) and
/// triangle = the key's low 32 bits (0 where nothing won). On SIMD lanes (dynamic dispatch).
/// Returns the number of pixels where something won.
size_t split_winners(const double* depth, const uint64_t* key, size_t n, float* out_depth, uint32_t* out_instance,
                   uint32_t* out_triangle);

/// The Highway target rasterise_tile dispatches to now (HWY_AVX2, HWY_EMU128, ...).
int64_t raster_simd_target();

}  // namespace silva::render
