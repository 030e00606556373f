#pragma once
/// @file A screen triangle set up for tile rasterisation (fixed-point edges, depth plane, key).
#include <cstdint>

#include "core/mesh.hpp"
#include "render/view_projection.hpp"

namespace silva::render {

/// Index value of RasterTri::alpha for a triangle without an alpha mask.
inline constexpr uint32_t kNoAlpha = 0xffffffffu;

/// One screen triangle with A > 0 (raster_conventions.hpp). Edge values are exact integers.
struct RasterTri {
  PixelPlane edge[3];      ///< E_i at pixel (x, y) incl. fill-rule bias; inside when all >= 0.
  PixelPlane depth;        ///< Reverse depth d at pixel centres.
  double depth_max = 0;    ///< Conservative upper bound of d over the triangle (early rejection).
  int32_t x0 = 0, y0 = 0;  ///< First covered-candidate pixel (inclusive, inside the image).
  int32_t x1 = 0, y1 = 0;  ///< Last covered-candidate pixel (inclusive, inside the image).
  uint64_t key = 0;        ///< instance << 32 | triangle: lower wins equal depth.
  uint32_t alpha = kNoAlpha;  ///< Index of the AlphaAttrib in the same store, or kNoAlpha.
};

/// A triangle's entry in one tile's bin: its index plus what the early depth test needs, so a
/// triangle behind everything in the blocks it touches is rejected without reading its RasterTri.
struct BinEntry {
  double depth_max = 0;  ///< RasterTri::depth_max.
  uint32_t index = 0;    ///< Index of the RasterTri in its store.
  uint8_t x0 = 0, y0 = 0;  ///< First candidate pixel inside the tile, tile-local (tiles are <= 256 px).
  uint8_t x1 = 0, y1 = 0;  ///< Last candidate pixel inside the tile, tile-local, inclusive.
};
static_assert(sizeof(BinEntry) == 16, "bins hold 4 entries per cache line");

/// What alpha testing needs at a pixel: barycentric planes, vertex uvs and the mask. At pixel
/// (x, y): b1 = n1.at/den.at, b2 = n2.at/den.at, uv = uv0 + b1 (uv1 - uv0) + b2 (uv2 - uv0) in
/// double, then mask->opaque(float(u), float(v)) (nearest texel, repeat wrap).
struct AlphaAttrib {
  PixelPlane n1, n2, den;       ///< b1 = n1/den, b2 = n2/den at pixel centres.
  Vec2f uv0, uv1, uv2;          ///< Vertex texture coordinates.
  const AlphaMask* mask = nullptr;  ///< Non-owning; the Scene outlives the pass.
};

}  // namespace silva::render
