#pragma once
/// @file Sutherland-Hodgman clipping of a convex view-space polygon against planes.
#include "render/view_projection.hpp"

namespace silva::render {

/// Most vertices a clipped triangle can have (3 + one per clip plane).
inline constexpr int kMaxClippedVertices = 3 + 5;

/// Clips the convex polygon `poly` (n vertices, room for kMaxClippedVertices) against each plane
/// in turn (inside: plane . (p, 1) >= 0) and returns the new vertex count (0 when nothing is
/// left). The point where an edge crosses a plane is computed from its endpoints in a canonical
/// order, so two triangles sharing that edge get bit-identical vertices.
int clip_polygon(const Vec4d* planes, int plane_count, Vec3d* poly, int n);

}  // namespace silva::render
