#pragma once
/// @file Sun visibility from a render::ShadowMap: normal offset + receiver-plane depth bias + round-filtered PCF.
#include "core/types.hpp"
#include "render/gbuffer.hpp"

namespace silva::render {

/// Fraction in [0, 1] of sun visibility at `position` (1 = lit): PCF over the 4x4 texels around it,
/// each weighing max(0, 1 - d^2 / 4) at d texels from the point (a round filter 2 texels in radius),
/// continuous in the position.
/// Texel (tx, ty) is depth[ty * width + tx] (convention in render/gbuffer.hpp). Against acne the
/// point is pushed one texel along its normal turned towards the sun, and each tap compares the
/// depth of the receiver's own plane extrapolated to that tap's texel centre (receiver-plane
/// depth bias, slope clamped), minus a small constant bias (half a texel + 2 cm), so contact
/// shadows stay attached (no peter-panning). Points outside the map are lit.
/// Light-space coordinates, slopes and tap offsets are computed in double, each tap's receiver
/// depth is rounded to float and compared with the texel, weights are summed in float, so every
/// Highway target gives the same bits.
float shadow_visibility(const ShadowMap& map, const Vec3f& position, const Vec3f& normal, const Vec3f& to_sun);

/// shadow_visibility of `count` points (positions[i], normals[i]) into out[i], on SIMD lanes.
void shadow_visibility_row(const ShadowMap& map, const Vec3f* positions, const Vec3f* normals, size_t count,
                           const Vec3f& to_sun, float* out);

/// The Highway target shadow_visibility_row dispatches to now.
int64_t shadow_simd_target();

}  // namespace silva::render
