#pragma once
/// @file Sun visibility from a render::ShadowMap: normal offset + receiver-plane depth bias + tent-filtered PCF.
#include "core/types.hpp"
#include "render/gbuffer.hpp"

namespace silva::render {

/// Fraction in [0, 1] of sun visibility at `position` (1 = lit): 3x3 bilinearly weighted PCF taps,
/// i.e. a tent filter over the 4x4 texels around it, continuous in the position.
/// Texel (tx, ty) is depth[ty * width + tx] (convention in render/gbuffer.hpp). Against acne the
/// point is pushed one texel along its normal turned towards the sun, and each tap compares the
/// depth of the receiver's own plane extrapolated to that tap's texel centre (receiver-plane
/// depth bias, slope clamped), minus a small constant bias (half a texel + 2 cm), so contact
/// shadows stay attached (no peter-panning). Points outside the map are lit.
float shadow_visibility(const ShadowMap& map, const Vec3f& position, const Vec3f& normal, const Vec3f& to_sun);

}  // namespace silva::render
