#pragma once
/// @file Incremental construction of a Mesh part by part, plus the primitive shapes the
/// procedural generators are made of (tapered tubes, discs, cards, icospheres).
#include <memory>
#include <span>
#include <vector>

#include "core/mesh.hpp"

namespace silva::assets {

/// Appends vertices and triangles to a Mesh, grouping triangles into parts.
class MeshBuilder {
 public:
  /// Starts a new part; the following triangles belong to it until the next begin_part.
  void begin_part(Role role, Material material, std::shared_ptr<const AlphaMask> mask = nullptr,
                  bool double_sided = false);
  /// Adds a vertex (normal is normalised) and returns its index.
  uint32_t vertex(const Vec3f& p, const Vec3f& n, const Vec2f& uv);
  /// Position of vertex `index` added so far.
  const Vec3f& position(uint32_t index) const { return mesh_.positions[index]; }
  /// Adds a counter-clockwise triangle to the current part.
  void triangle(uint32_t a, uint32_t b, uint32_t c);
  /// Finishes and returns the mesh (empty parts dropped).
  Mesh finish();

 private:
  Mesh mesh_;
};

/// A point on a tube's centre line with the tube radius there.
struct TubeNode {
  Vec3f p;         ///< Centre-line point.
  float r;         ///< Radius at the point (m).
  float lobe = 0;  ///< Lobe height over r (TubeLobes); 0: round.
};

/// Ridges along a tube (a trunk's buttresses): the radius at angle a of the tube's frame is
/// r (1 + lobe ridge(a)), ridge(a) = max(0, cos(count (a - phase)))^4, so ridges with rounded
/// valleys between them.
struct TubeLobes {
  int count = 0;     ///< Ridges around the tube (0: round).
  float phase = 0;   ///< Angle of the first ridge (radians).
  /// ridge(a), in [0, 1].
  float ridge(float a) const;
};

/// Adds a closed-side tube along a polyline (>= 2 nodes) with `segments` sides; smooth normals
/// account for the taper and the lobes; u goes around (seam duplicated), v along the length in
/// metres / 2, or, when `v_height` > 0, v = the node's z / v_height (a tree's height fraction, for
/// bark by height). With `end_ring`, its last ring's `segments` points (counter-clockwise about the tube's
/// direction at its end) are written there.
void add_tube(MeshBuilder& b, std::span<const TubeNode> nodes, int segments, float v_height = 0,
              const TubeLobes& lobes = {}, std::vector<Vec3f>* end_ring = nullptr);

/// Adds a flat disc (fan) of `segments` sides facing `normal`.
void add_disc(MeshBuilder& b, const Vec3f& center, const Vec3f& normal, float radius, int segments);

/// Adds a single quad card: centre, half-width vector `right` and half-height vector `up`;
/// uv (0,0) at centre - right + up (top-left), front face towards right x up.
void add_card(MeshBuilder& b, const Vec3f& center, const Vec3f& right, const Vec3f& up);

/// A unit icosphere (radius 1) with `subdivisions` levels; shared vertices, outward normals.
Mesh unit_icosphere(int subdivisions);

/// Two unit vectors perpendicular to `axis` and to each other (a right-handed frame).
void perpendicular_frame(const Vec3f& axis, Vec3f& u, Vec3f& v);

}  // namespace silva::assets
