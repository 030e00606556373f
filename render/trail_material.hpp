#pragma once
/// @file The trail's look (Material::Trail), painted into the ground by the terrain's overlay
/// (core/surface_overlay.hpp), in the family SurfacePoint::trail names (core/trail_surface.hpp):
/// packed earth (compacted light soil, embedded stones, roots crossing), gravel, roots (dark eroded
/// soil, many roots), leaf-covered (litter over all but the trodden line), muddy (dark wet mud, water
/// standing in two ruts) or grass ruts (two bare ruts with grass between and beside them). Every
/// family has litter drifting in from the sides and a worn, grassy fringe outside the edge that fades
/// into the forest floor. Expects uv.x = signed distance to the trail's edge (metres, negative on the
/// trail) and uv.y = arc length along the trail (metres), as world/terrain.hpp writes them.
#include "render/materials.hpp"

namespace silva::render {

/// The least wetness of a muddy trail, in any weather (render/weather_look.hpp).
inline constexpr float kMudWetness = 0.3f;

/// Linear-RGB albedo of a trail-material point: the forest floor blended into the trail look by
/// overlay_weight, so it is exactly half of each on the label edge and the floor at kOverlayMargin.
Vec3f trail_albedo(const SurfacePoint& s);

/// trail_albedo over `floor`, the forest floor's albedo under the point (ground_albedo_row of its position,
/// normal and footprint), for callers that evaluate the floor of many points at once.
Vec3f trail_albedo_on(const SurfacePoint& s, const Vec3f& floor);

/// Water standing in a muddy trail's ruts at `s`, 0 … 1, in any weather (elongated pools along the
/// ruts, about a third of their length); 0 for every other family and off the trail band.
float trail_standing_water(const SurfacePoint& s);

}  // namespace silva::render
