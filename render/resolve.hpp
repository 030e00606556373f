#pragma once
/// @file Resolve: from the visibility buffer to the G-buffer by exact re-intersection at pixel centres.
#include <cstdint>
#include <span>

#include "core/camera.hpp"
#include "render/gbuffer.hpp"
#include "render/mask_cache.hpp"
#include "render/scene.hpp"
#include "render/visibility.hpp"

namespace silva::render {

/// Fills every pixel of `out` (resized to the camera when needed): for a hit, re-intersects the
/// pixel's centre ray with the stored triangle in double (Moller-Trumbore) and writes metric z,
/// world position, the interpolated vertex normal turned to face the camera, uv, the part's role
/// and material (or its overlay's, core/surface_overlay.hpp), the instance's id and variation, and
/// a masked part's leaf alpha from the mask's leaf mips at the pixel's footprint (render/leaf_mips.hpp);
/// a miss gets depth 0 and role Background.
/// `instance_lod` is the LOD each instance was drawn with; `masks` holds the scene's masks (MaskCache::update).
void resolve_gbuffer(const Scene& scene, const Camera& camera, const VisibilityBuffer& vis,
                     std::span<const uint32_t> instance_lod, const MaskCache& masks, GBuffer& out);

}  // namespace silva::render
