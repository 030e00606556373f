#pragma once
/// @file Triangle-setup vertices of many mesh vertices at once, on Highway SIMD lanes (runtime dispatch).
#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

#include "core/types.hpp"
#include "render/triangle_setup.hpp"
#include "render/view_projection.hpp"

namespace silva::render {

/// Fills out[i] for positions[i], i < count, exactly as the scalar triangle setup would for a
/// perspective `view` (every vertex in front of the camera): p = m * (x, y, z, 1) in double, each
/// row as ((m(r,0) x + m(r,1) y) + m(r,2) z) + m(r,3); x = round_half_away((fx * p.x / p.z + cx) * 256),
/// y likewise with fy, cy; depth = 1 / p.z; projected = true. Lane by lane in that operation order,
/// so every Highway target gives the scalar bits.
void project_vertices(const Eigen::Matrix<double, 3, 4>& m, const ViewProjection& view, const Vec3f* positions,
                      size_t count, SetupVertex* out);

/// The Highway target project_vertices dispatches to now.
int64_t vertex_simd_target();

}  // namespace silva::render
