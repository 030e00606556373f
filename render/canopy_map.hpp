#pragma once
/// @file How much of the sky a surface point sees past the forest canopy, from a top-down depth map of
/// the scene (the shadow pass drawn straight down): the canopy's cover and depth on coarse cells,
/// box-blurred over a few metres, looked up per pixel (a sky-visibility term for the ambient light
/// that sees the trees above, the same at every time of day).
#include <functional>
#include <vector>

#include "core/aabb.hpp"
#include "core/types.hpp"
#include "render/gbuffer.hpp"

namespace silva::render {

/// Texel of the top-down depth map the canopy map is made from, metres.
inline constexpr double kCanopyTexel = 0.5;
/// Smallest bounding-sphere radius (m) of an object the top-down depth map draws: smaller ones (ground
/// cover, rocks, saplings) cannot reach kCanopyHeight with a crown worth counting.
inline constexpr double kCanopyMinRadius = 2.0;
/// Side of one canopy cell, metres (kCanopyTexel / kCanopyCell squared texels make its cover).
inline constexpr double kCanopyCell = 0.5;
/// A shadow-map texel counts as canopy when its surface is this many metres above the ground under it.
inline constexpr double kCanopyHeight = 2.0;
/// Radius, metres, of the box the cover is averaged over (how far around a point the canopy shades it).
inline constexpr double kCanopyRadius = 6.0;
/// Radius, metres, of the stand around a point whose crowns hide the lower sky from it (a gap of a few metres
/// among 20-30 m trees sees little more than its zenith).
inline constexpr double kCanopyStandRadius = 15.0;
/// Weight of the stand's cover: the sky a point sees is (1 - near cover) x (1 - kCanopyStandWeight x stand cover).
inline constexpr float kCanopyStandWeight = 1.0f;
/// Light-space depth, metres, over which a point goes from above the canopy's mean depth to below it.
inline constexpr double kCanopySoftness = 4.0;
/// Share of the sky light a fully covering canopy takes from a point below it (the rest are gaps).
inline constexpr float kCanopyDensity = 1.0f;

/// Ground height (metres) at world (x, y).
using GroundHeight = std::function<double(double, double)>;

/// Canopy cover and mean canopy depth on light-space cells of kCanopyCell metres, blurred.
struct CanopyMap {
  int width = 0, height = 0;      ///< Cells across and down (0 = no map: every point sees the sky).
  Mat4d world_to_light = Mat4d::Identity();  ///< The depth map's world -> light transform.
  double cell = kCanopyCell;      ///< Metres per cell.
  double origin_x = 0, origin_y = 0;  ///< Light-space x, y of cell (0, 0)'s lower corner.
  std::vector<float> cover;       ///< Blurred vertical canopy cover per cell, row-major.
  std::vector<float> depth;       ///< Blurred mean light-space depth of those texels (0 where cover is 0).
};

/// The region a canopy map must cover so that every point of `shaded` gets its whole blur windows: `shaded`
/// grown by kCanopyStandRadius in x and y (past a map's edge counts as no canopy, so a map of `shaded`
/// alone would light the points near its edges, the camera's own spot among them, as if the trees
/// beyond were not there).
AABB canopy_region(const AABB& shaded);

/// The canopy of `shadow`: per cell, the texels whose surface lies kCanopyHeight or more above the
/// ground (`ground` under the cell's farthest surface, refined once along the light), their share
/// and mean depth, box-blurred over kCanopyRadius (the crowns near) and over kCanopyStandRadius (the
/// stand), the two covers combined as 1 - (1 - near)(1 - kCanopyStandWeight stand) and their depths
/// by cover. Cells run in parallel; the result never depends on threads.
CanopyMap build_canopy_map(const ShadowMap& shadow, const GroundHeight& ground);

/// Share in [0, 1) of the sky light the canopy takes from each of `count` world points: with the vertical gap
/// fraction g = 1 - kCanopyDensity x cover x how far the point lies below the canopy's mean depth (bilinear
/// between cells), 1 - g^1.5 (a turbid layer's diffuse transmittance over the cosine-weighted sky, within
/// 0.05 of 2∫g^(1/μ)μ dμ for g ≥ 0.1); 0 outside the map.
void canopy_share_row(const CanopyMap& map, const Vec3f* positions, size_t count, float* out);

}  // namespace silva::render
