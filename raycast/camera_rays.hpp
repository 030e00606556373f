#pragma once
/// @file Camera rays through pixel centres (CONTRACT.md: pixel (u, v) sees K^-1 (u + 0.5, v + 0.5, 1)),
/// cast through a RayScene in coherent 4x4 pixel blocks.
#include <cstdint>
#include <span>
#include <vector>

#include "core/camera.hpp"
#include "raycast/ray_scene.hpp"

namespace silva::raycast {

/// Every pixel index (y * width + x) of a width x height image, ordered by 4x4 blocks (blocks
/// row-major, pixels row-major within a block), so that each packet of 16 is one coherent block.
std::vector<uint32_t> block_order(int width, int height);

/// Casts the rays of `camera` through the centres of `pixels` (indices y * width + x, best in
/// block_order) into `hits` (same size): from the camera centre, t_near = near, t_far = far, the
/// direction scaled to camera z = 1 so that a hit's t is its depth along the optical axis. The
/// ground-cover cut-offs are measured from the camera centre; `exact_masks` as CastOptions::exact_masks.
void cast_pixels(const RayScene& scene, const Camera& camera, std::span<const uint32_t> pixels,
                 std::span<RayHit> hits, bool exact_masks = false);

}  // namespace silva::raycast
