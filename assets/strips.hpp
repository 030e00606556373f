#pragma once
/// @file Bent strips of quads for plant parts: fronds, blades and leaves along a curved spine,
/// and thin stems drawn as two crossed ribbons (thin tubes alias into dotted lines).
#include <span>
#include <vector>

#include "assets/mesh_builder.hpp"

namespace silva::assets {

/// A point of a strip's spine with the strip's half-width there.
struct StripNode {
  Vec3f p;            ///< Spine point.
  float half_width;   ///< Half-width across the strip (m).
};

/// Adds a strip of quads along `spine` (>= 2 nodes) spreading along `side` (made perpendicular to
/// the spine at each node). u runs 0..1 across along `side`, v from 1 at the first node to 0 at the
/// last (masks draw their base at v = 1); the front faces side x tangent. The first two vertices
/// added are the base edge.
void add_strip(MeshBuilder& b, std::span<const StripNode> spine, const Vec3f& side);

/// Points of a quadratic Bezier from a through control c to b, `segments` + 1 of them.
std::vector<Vec3f> bezier(const Vec3f& a, const Vec3f& c, const Vec3f& b, int segments);

/// Adds a stem along `nodes` as two crossed ribbons of width 2 r; the caller has begun a
/// double-sided part.
void add_ribbon_stem(MeshBuilder& b, std::span<const TubeNode> nodes);

/// Unit horizontal direction at azimuth `az` (radians from +X).
Vec3f horizontal(float az);

}  // namespace silva::assets
