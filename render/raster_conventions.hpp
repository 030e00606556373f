#pragma once
/// @file Conventions of Silva's software rasteriser. Every raster_* file follows this page.
///
/// Spaces
///   - World: right-handed, metres, Z up.
///   - View space: the camera's OpenCV axes (x right, y down, z forward) for the perspective
///     camera; for the orthographic sun view, light space (x, y across the map, z increasing
///     away from the sun, right-handed). Both views look along +z.
///   - Screen: continuous pixel coordinates (u, v), u right, v DOWN; pixel (x, y) covers
///     [x, x+1) x [y, y+1) and its single sample is its centre (x + 0.5, y + 0.5) (COLMAP).
///     Perspective: u = fx * x / z + cx. Orthographic: u = fx * x + cx (fx = 1 / texel size).
///
/// Winding
///   - Front faces are counter-clockwise seen from outside in object space (core/mesh.hpp),
///     i.e. their normal n = (p1 - p0) x (p2 - p0) points out of the object.
///   - A face is front-facing when the view sees its outside: p0 . n < 0 in view space
///     (perspective; the eye is the origin) or n.z < 0 (orthographic; the view looks along +z).
///     The test is done in double in view space on the unclipped triangle.
///   - Because v grows downwards, a front face has NEGATIVE signed screen area
///     A = (x1-x0)(y2-y0) - (y1-y0)(x2-x0). The rasteriser only draws triangles with A > 0
///     ("clockwise on the y-down screen", as Direct3D); front faces get v1 and v2 swapped,
///     visible back faces (double-sided parts, or culling off) are drawn as they are.
///     A sub-triangle whose snapped area has the wrong sign or is zero is a sliver and is dropped.
///
/// Fixed point and fill rule
///   - Vertices are snapped to 1/256 pixel (kSubpixelBits = 8): X = round_half_away(u * 256) (llround).
///   - Edge a->b of an A > 0 triangle: E(p) = (bx-ax)(py-ay) - (by-ay)(px-ax); inside is E >= 0.
///     Edge values are exact integers (|E| < 2^50) held in doubles, so SIMD lanes of doubles
///     evaluate them exactly on every Highway target.
///   - Top-left rule (Direct3D): an edge with dy < 0 (left) or dy == 0 && dx > 0 (top) owns
///     samples exactly on it; other edges do not (their E gets a bias of -1).
///   - Triangles are clipped against the near plane and, only when they leave it, a guard band
///     of kGuardBandPixels around the image; intersection points are computed from the edge's
///     endpoints in a canonical order so neighbouring triangles get identical vertices.
///
/// Depth
///   - Reverse depth: the stored value d grows towards the viewer. Perspective d = 1/z,
///     orthographic d = -z. d is affine in screen space; its plane comes analytically from the
///     view-space triangle in double and is evaluated per pixel as (c + b*y) + a*x.
///   - A sample wins when d > stored, or d == stored and its key (instance << 32 | triangle) is
///     lower. That is a total order, so the result does not depend on submission order,
///     binning order or thread count. Perspective views start at d = 1/far: z <= far is a hit.
///   - Early rejection: each 8x8 block keeps the minimum stored d; a triangle whose conservative
///     maximum d is below it is skipped for that block (never changes the result), and so is a
///     block where the triangle's depth plane, at the corner of the covered part its slopes point
///     to, is below it (rounding is monotone, so no pixel there computes a larger d), or where one
///     edge function is negative over the whole part the triangle's bounds cover.
///     Bin entries carry the maximum d and the bounds, so a triangle hidden in every block it
///     touches is skipped without reading its RasterTri. Instances are drawn nearest first (by
///     their bounding spheres) so more blocks are full early.
///   - The G-buffer's metric depth is not read back from d: the resolve re-intersects the pixel's
///     centre ray with the stored triangle in double.
#include <cstdint>

namespace silva::render {

/// Sub-pixel precision of snapped vertices, in bits.
inline constexpr int kSubpixelBits = 8;
/// Sub-pixel steps per pixel.
inline constexpr int64_t kSubpixelScale = int64_t(1) << kSubpixelBits;
/// Guard band around the image, in pixels: triangles inside it are not clipped at the sides.
inline constexpr double kGuardBandPixels = 8192.0;
/// Largest image or shadow-map side the rasteriser accepts (keeps edge values exact in doubles).
inline constexpr int kMaxRasterSize = 16384;
/// Side of the early-depth-rejection blocks, in pixels.
inline constexpr int kDepthBlockSize = 8;
/// Visibility-buffer instance value of a pixel that saw nothing.
inline constexpr uint32_t kNoInstance = 0xffffffffu;
/// Key of an empty sample (loses every tie).
inline constexpr uint64_t kNoKey = ~uint64_t(0);

}  // namespace silva::render
