#pragma once
/// @file A screen triangle set up for tile rasterisation (fixed-point edges, depth plane, key).
#include <cstdint>

#include "core/mesh.hpp"
#include "render/mask_cache.hpp"
#include "render/raster_conventions.hpp"
#include "render/view_projection.hpp"

namespace silva::render {

/// Index value of RasterTri::alpha for a triangle without an alpha mask.
inline constexpr uint32_t kNoAlpha = 0xffffffffu;

/// An edge function over pixel indices, E(x, y) = (c + b*y) + a*x with a = -256*dy and
/// b = 256*dx (raster_conventions.hpp). Every value is an exact integer held in a double.
struct EdgeFunction {
  double c = 0;     ///< E at pixel (0, 0)'s centre, fill-rule bias included.
  int32_t dx = 0;   ///< The edge's x extent in 1/256 pixel (|dx| < 2^24 inside the guard band).
  int32_t dy = 0;   ///< The edge's y extent in 1/256 pixel.
  /// Change of E per pixel to the right.
  double a() const { return -double(kSubpixelScale) * double(dy); }
  /// Change of E per pixel down.
  double b() const { return double(kSubpixelScale) * double(dx); }
  /// E at pixel (x, y)'s centre.
  double at(double x, double y) const { return (c + b() * y) + a() * x; }
};

/// One screen triangle with A > 0 (raster_conventions.hpp), as the tile rasteriser reads it.
/// Kept small: a frame writes and reads back hundreds of thousands of them.
struct RasterTri {
  EdgeFunction edge[3];       ///< Inside when all three are >= 0 at a pixel centre.
  PixelPlane depth;           ///< Reverse depth d at pixel centres.
  uint64_t key = 0;           ///< instance << 32 | triangle: lower wins equal depth.
  uint32_t alpha = kNoAlpha;  ///< Index of the AlphaAttrib in the same store, or kNoAlpha.
};

/// Where a set-up screen triangle may cover sample centres and how near it can come: what
/// binning needs, handed over beside the RasterTri rather than stored in it.
struct TriBounds {
  int32_t x0 = 0, y0 = 0;  ///< First covered-candidate pixel (inclusive, inside the image).
  int32_t x1 = 0, y1 = 0;  ///< Last covered-candidate pixel (inclusive, inside the image).
  double depth_max = 0;    ///< Conservative upper bound of d over the triangle (early rejection).
};

/// A triangle's entry in one tile's bin: its index plus what the early depth test needs, so a
/// triangle behind everything in the blocks it touches is rejected without reading its RasterTri.
struct BinEntry {
  double depth_max = 0;  ///< TriBounds::depth_max.
  uint32_t index = 0;    ///< Index of the RasterTri in its store.
  uint8_t x0 = 0, y0 = 0;  ///< First candidate pixel inside the tile, tile-local (tiles are <= 256 px).
  uint8_t x1 = 0, y1 = 0;  ///< Last candidate pixel inside the tile, tile-local, inclusive.
};
static_assert(sizeof(BinEntry) == 16, "bins hold 4 entries per cache line");

/// What alpha testing needs at a pixel: perspective-correct texture coordinates as ratios of
/// planes, and the mask's opacity bits. At pixel (x, y): U = u.at(x, y), V = v.at(x, y) and
/// W = w.at(x, y) in double, then s = float(U) / float(W), t = float(V) / float(W) in float, and
/// the pixel is opaque when bits->opaque(s, t) (nearest texel, repeat wrap).
struct AlphaAttrib {
  PixelPlane u, v, w;               ///< U / W and V / W are the texture coordinates.
  const AlphaBits* bits = nullptr;  ///< Non-owning; the renderer's MaskCache outlives the pass.
};

}  // namespace silva::render
