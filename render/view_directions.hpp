#pragma once
/// @file The unit view direction of every pixel of an image row, on SIMD lanes.
#include <cstdint>

#include "core/camera.hpp"

namespace silva::render {

/// camera.ray_direction(u, v).normalized().cast<float>() for every column u of row v, into
/// out[0 .. camera.width): the same double operations in the same order on SIMD lanes (Eigen's
/// association of the 3x3 product and of the squared norm), so the floats are the same bits.
void view_directions_row(const Camera& camera, int v, Vec3f* out);

/// The Highway target view_directions_row dispatches to now.
int64_t view_directions_simd_target();

}  // namespace silva::render
