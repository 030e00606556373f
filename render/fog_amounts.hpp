#pragma once
/// @file Height-fog amounts of many points at once, on Highway SIMD lanes (runtime dispatch).
#include <cstddef>
#include <cstdint>

#include "core/types.hpp"

namespace silva::render {

/// The constants of one fog and camera that the per-point fog amount needs (HeightFog fills them).
struct FogAmountParams {
  Vec3f camera = Vec3f::Zero();  ///< Camera position.
  float falloff = 0;             ///< Height falloff (1/m), >= 0.
  float camera_density = 0;      ///< Fog density at the camera height; <= 0 means no fog.
};

/// out[i] = fraction in [0, 1) of the view towards points[i] replaced by fog: with d = p - camera,
/// k = falloff * d.z and the mean height factor h = (1 - e^-k) / k (its series
/// 1 - k (1/2 - k/6) when |k| < 1e-2), 1 - e^-(camera_density * |d| * h). |d| is
/// sqrt(dx^2 + (dy^2 + dz^2)) and e^x is det_expf's polynomial, lane by lane in that operation
/// order, so every Highway target gives the same bits.
void fog_amounts(const FogAmountParams& fog, const Vec3f* points, size_t count, float* out);

/// The Highway target fog_amounts dispatches to now.
int64_t fog_simd_target();

}  // namespace silva::render
