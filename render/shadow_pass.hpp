#pragma once
/// @file Sun shadow maps: the light-space frame and texel grid, and depth from a visibility pass.
#include "core/aabb.hpp"
#include "core/types.hpp"
#include "render/gbuffer.hpp"
#include "render/view_projection.hpp"
#include "render/visibility.hpp"

namespace silva::render {

/// A shadow map's frame for a sun direction (towards the sun, any length > 0) covering the
/// light-space footprint of the world box `region` with square texels, `resolution` of them
/// along the footprint's longer side and as few as cover the shorter one (convention in
/// gbuffer.hpp); depth is left empty. Throws InputError for a zero or non-finite direction, an empty region or a
/// resolution outside [1, kMaxRasterSize].
ShadowMap shadow_map_frame(const Vec3d& direction_to_sun, const AABB& region, int resolution);

/// The orthographic view that rasterises a shadow map's texel grid.
ViewProjection shadow_view(const ShadowMap& map);

/// Fills map.depth from a visibility pass of shadow_view(map): light-space z, +inf for no hit.
void shadow_depth_from_visibility(const VisibilityBuffer& vis, ShadowMap& map);

}  // namespace silva::render
