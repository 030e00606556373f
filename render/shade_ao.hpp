#pragma once
/// @file Cheap screen-space ambient occlusion from the G-buffer's world positions and normals.
#include <cstdint>

#include "core/camera.hpp"
#include "render/gbuffer.hpp"

namespace silva::render {

/// World radius (metres) within which neighbouring surfaces occlude ambient light.
inline constexpr float kAoRadius = 0.6f;

/// Ambient visibility in [0, 1] (1 = open) of pixel (u, v), which must have a hit: 8 neighbours
/// in a fixed pattern within 0.6 kAoRadius (projected); each one above the pixel's tangent plane and
/// closer than kAoRadius occludes in proportion to its elevation and closeness. Pure function.
float screen_space_ao(const GBuffer& g, const Camera& camera, int u, int v);

/// screen_space_ao of pixels (u0 + k step, v), k < count, into out[k], one pixel per SIMD lane;
/// each lane runs the scalar operations in the same order, so every Highway target agrees.
/// Pixels without a hit get a meaningless value (callers skip them).
void screen_space_ao_row(const GBuffer& g, const Camera& camera, int v, int u0, int step, int count, float* out);

/// screen_space_ao of pixels (columns[k], v), k < count, into out[k]: the same values as
/// screen_space_ao_row gives those pixels (each lane runs the same operations).
void screen_space_ao_columns(const GBuffer& g, const Camera& camera, int v, const int32_t* columns, int count,
                             float* out);

/// The Highway target screen_space_ao_row dispatches to now.
int64_t ao_simd_target();

}  // namespace silva::render
