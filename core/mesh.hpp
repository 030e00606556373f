#pragma once
/// @file Triangle meshes with per-part semantic roles and materials.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/aabb.hpp"
#include "core/base_color.hpp"
#include "core/material.hpp"
#include "core/ontology.hpp"
#include "core/types.hpp"

namespace silva {

/// An alpha mask for foliage cards: sampled nearest-texel, repeat wrap, no mipmaps.
struct AlphaMask {
  int width = 0;                 ///< Texels across.
  int height = 0;                ///< Texels down (row 0 is v in [0, 1/height)).
  std::vector<uint8_t> alpha;    ///< width*height alpha values, row-major (opaque 128..254: a leaf's brightness).
  float cutoff = 0.5f;           ///< A texel is opaque when alpha/255 >= cutoff.
  float feature_length = 0.0f;   ///< Typical leaf or needle length in texture units (0: not recorded).
  /// Nearest-texel lookup with repeat wrap: true when (u, v) is opaque (|u|, |v| < 2^31).
  bool opaque(float u, float v) const { return opaque_texel(texel(v, height) * width + texel(u, width)); }
  /// True when texel i (row-major) is opaque.
  bool opaque_texel(int i) const { return float(alpha[size_t(i)]) >= cutoff * 255.0f; }
  /// Texel index of coordinate t wrapped into [0, 1) over n texels: floor without a libm call.
  static int texel(float t, int n) {
    float f = float(int(t));
    if (f > t) f -= 1.0f;
    const int i = int((t - f) * float(n));
    return i >= n ? n - 1 : i;
  }
};

/// A second role and material painted into a part by its uv.x (a signed distance in metres to the
/// overlay's edge, negative inside): core/surface_overlay.hpp turns it into a blend weight with a
/// ragged edge; pixels whose weight reaches 0.5 take `role`, those it touches take `material`.
struct PartOverlay {
  Role role = Role::Trail;              ///< Class where the overlay weight is at least 0.5.
  Material material = Material::Trail;  ///< Material that blends the overlay into the part's own look.
};

/// A contiguous range of triangles sharing a role, material and mask.
struct MeshPart {
  uint32_t first_index = 0;    ///< Offset into Mesh::indices (multiple of 3).
  uint32_t index_count = 0;    ///< Number of indices (multiple of 3).
  Role role = Role::Ground;    ///< Semantic role of these triangles.
  Material material = Material::Ground;  ///< Procedural material (also decides leaf translucency).
  std::shared_ptr<const BaseColor> base_color;  ///< The asset file's own colour, or null: procedural albedo.
  std::shared_ptr<const AlphaMask> mask;  ///< Alpha mask (foliage cards), or null.
  bool double_sided = false;   ///< Disable back-face culling for this part.
  std::optional<PartOverlay> overlay;  ///< Painted by uv.x (the trail in the terrain), or none.
};

/// Indexed triangle mesh in object space (metres, Z up), counter-clockwise front faces.
struct Mesh {
  std::vector<Vec3f> positions;     ///< Vertex positions.
  std::vector<Vec3f> normals;       ///< Unit vertex normals (same count as positions).
  std::vector<Vec2f> uvs;           ///< Texture coordinates (same count as positions).
  std::vector<uint32_t> indices;    ///< Triangle list.
  std::vector<MeshPart> parts;      ///< Parts covering indices in order.
  /// Number of triangles.
  size_t triangle_count() const { return indices.size() / 3; }
  /// Bounds of all positions.
  AABB bounds() const;
  /// Recomputes area-weighted smooth vertex normals from the triangles.
  void compute_normals();
  /// Appends another mesh (its parts keep their roles/materials).
  void append(const Mesh& other);
};

/// A mesh with `source`'s parts but new triangles: part p gets `part_indices[p]` (indices into
/// `positions`, which stands in for source's positions and has their count). Keeps only the
/// vertices used, in their original order, with source's normals and uvs.
Mesh compact_mesh(const Mesh& source, const std::vector<Vec3f>& positions,
                  const std::vector<std::vector<uint32_t>>& part_indices);

}  // namespace silva
