#pragma once
/// @file Parts shared by the shrub generators: woody stems (tubes where thick, crossed ribbons
/// where thinner than kMinTubeRadius) and leaf cards placed along them.
#include <vector>

#include "assets/mesh_builder.hpp"
#include "core/rng.hpp"

namespace silva::assets {

/// Stems thinner than this radius (m) are drawn as crossed ribbons, not tubes.
inline constexpr float kMinTubeRadius = 0.015f;

/// One stem or branch: a polyline with radii, base first.
using StemNodes = std::vector<TubeNode>;

/// Adds every stem: the thick part of each (radius >= kMinTubeRadius) as a tube in one part,
/// the rest as crossed ribbons in a second, double-sided part; both get `role` and `material`.
void add_stems(MeshBuilder& b, const std::vector<StemNodes>& stems, Role role, Material material);

/// Point at fraction t in [0, 1] of a stem's nodes (by node index, linear between nodes).
Vec3f stem_point(const StemNodes& stem, float t);

/// A stem along a quadratic Bezier from `a` through control `c` to `b`, radius r0 at the base
/// tapering to r1, `segments` + 1 nodes.
StemNodes bent_stem(const Vec3f& a, const Vec3f& c, const Vec3f& b, float r0, float r1, int segments);

/// Adds a leaf card of half-size `half` centred at `center`, facing `facing` tilted by up to
/// `spread` (random) and spun randomly about it; the caller has begun the masked part.
void add_leaf_card(MeshBuilder& b, Rng& rng, const Vec3f& center, const Vec3f& facing, float spread, float half);

/// Adds a leaf card whose bottom edge (v = 1) sits at `base`, reaching `len` along `dir` and
/// facing as close to up as `dir` allows, rolled by up to `roll` radians.
void add_stalked_card(MeshBuilder& b, Rng& rng, const Vec3f& base, const Vec3f& dir, float len, float roll);

}  // namespace silva::assets
