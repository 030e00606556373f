#pragma once
/// @file Edge antialiasing for the final 8-bit RGB image: a post filter in the spirit of FXAA's
/// sub-pixel pass. Label and depth images never go through it (they stay exact per pixel).
#include <cstdint>
#include <vector>

namespace silva::render {

/// Smooths aliased edges of `rgb` (R, G, B bytes, row-major, width*height*3) into `out` (resized).
/// A pixel whose 3x3 luma contrast is low is copied unchanged; otherwise it is blended towards the
/// neighbour across the edge by up to 3/8, more the more it stands out from its neighbourhood.
/// Border pixels are copied. Rows run in parallel on the caller's TBB arena; the result does not
/// depend on the thread count.
void smooth_edges(const std::vector<uint8_t>& rgb, int width, int height, std::vector<uint8_t>& out);

}  // namespace silva::render
