#pragma once
/// @file The coverage blend of render/foliage_aa.hpp for the inside of a row on Highway SIMD lanes
/// (runtime dispatch), a pixel per lane.
#include <cstdint>

namespace silva::render {

/// One row of the frame with its blend inputs, per pixel: radiance (3 floats), layer depth, minified
/// weight, tone weight, and whether a minified mask lies within one pixel along the row (0 or 1).
struct BlendRowPlanes {
  const float* rgb;
  const float* layer;
  const float* weight;
  const float* tone;
  const uint8_t* near;
};

/// Blends columns [begin, end) of a row whose neighbours above and below exist (`rows`: above, at,
/// below; every column from begin - 1 to end readable) into out (3 floats per pixel, column begin
/// first); pixels with no minified mask within one pixel keep their radiance. Returns the first column
/// not written: the lanes take whole vectors only, the caller blends the rest. Each value is
/// MaskBlendRows's: the same correctly rounded float operations in the same order (no MulAdd), so
/// every target gives the same bits.
int blend_inside_lanes(const BlendRowPlanes rows[3], int begin, int end, float* out);

}  // namespace silva::render
