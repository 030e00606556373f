#pragma once
/// @file Where a run of an instance's vertices lies relative to a view, so the geometry pass can
/// drop a run wholly outside the view and set up on SIMD lanes a run that needs no clipping, even
/// when the instance as a whole straddles the view.
#include <cstdint>
#include <span>

#include "core/types.hpp"
#include "render/triangle_setup.hpp"

namespace silva::render {

/// Placement of a set of view-space points against a view's planes.
enum class Placement : uint8_t {
  Outside,    ///< Every point is behind one frustum plane: no triangle of them can be drawn.
  Inside,     ///< Every point is in front of every frustum and clip plane: no triangle needs a test.
  Unclipped,  ///< Every point is in front of every clip plane, not of every frustum plane: no
              ///< triangle needs clipping, each needs the frustum test.
  Straddles,  ///< A point may be behind a clip plane (or is not finite): triangles are tested and
              ///< clipped one by one.
};

/// Places the object-space points `positions` (all of them) transformed by `m` (object -> view)
/// against `sv`'s frustum and clip planes, through the corners of their bounding box with a
/// relative margin of 1e-9 that covers rounding, so the verdict is the one the per-triangle
/// tests of triangle_setup would reach for every triangle of these points.
Placement place_points(std::span<const Vec3f> positions, const Eigen::Matrix<double, 3, 4>& m, const SetupView& sv);

}  // namespace silva::render
