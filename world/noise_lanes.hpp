#pragma once
/// @file Fractal simplex noise (core/noise.hpp's fbm2) for many points at once, on SIMD lanes.
#include <cstddef>
#include <cstdint>

#include "core/noise.hpp"

namespace silva::world {

/// out[k] = fbm2(params, x[k], y[k]) for k < n: the scalar function's double operations in its order
/// (no fused multiply-add, exact floors, the same permutation), so every target returns its bits.
void fbm2_lanes(const FbmParams& params, const double* x, const double* y, double* out, size_t n);

/// The Highway target fbm2_lanes dispatches to now.
int64_t fbm2_lanes_simd_target();

}  // namespace silva::world
