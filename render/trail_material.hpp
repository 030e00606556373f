#pragma once
/// @file The trail's look (Material::Trail), painted into the ground by the terrain's overlay
/// (core/surface_overlay.hpp): compacted, lighter soil with embedded stones and roots crossing,
/// litter drifting in from the sides, and a worn, grassy fringe outside the edge that fades into
/// the forest floor. Expects uv.x = signed distance to the trail's edge (metres, negative on the
/// trail) and uv.y = arc length along the trail (metres), as world/terrain.hpp writes them.
#include "render/materials.hpp"

namespace silva::render {

/// Linear-RGB albedo of a trail-material point: the forest floor blended into the trail look by
/// overlay_weight, so it is exactly half of each on the label edge and the floor at kOverlayMargin.
Vec3f trail_albedo(const SurfacePoint& s);

}  // namespace silva::render
