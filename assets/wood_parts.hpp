#pragma once
/// @file Parts of the dead-wood generators (logs, stumps, fallen branches): bark surfaces as
/// closed grids of rings, and end caps that are sawn flat or broken into jagged splinters.
#include <span>
#include <vector>

#include "assets/mesh_builder.hpp"
#include "core/rng.hpp"

namespace silva::assets {

/// Adds a closed surface from `rows` rings of `cols` points (row-major, rings along the axis,
/// points counter-clockwise seen from the last ring); normals from neighbouring points (outward),
/// u around (seam duplicated), v along the axis in metres / 2.
void add_ring_grid(MeshBuilder& b, std::span<const Vec3f> p, int rows, int cols);

/// Adds an end cap over `ring` (the surface's end ring, counter-clockwise about `axis`, which
/// points out of the wood). jag = 0: a flat sawn face; jag > 0: a broken end whose splinters
/// reach up to jag x the ring radius out along the axis.
void add_end_cap(MeshBuilder& b, Rng& rng, std::span<const Vec3f> ring, const Vec3f& axis, float jag);

/// Ring of `cols` points around `center` in the plane perpendicular to unit `axis`, counter-
/// clockwise about it, at radius r(angle) given per point in `radii`; starts along frame u.
std::vector<Vec3f> ring_points(const Vec3f& center, const Vec3f& axis, const Vec3f& u, std::span<const float> radii);

}  // namespace silva::assets
