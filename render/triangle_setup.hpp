#pragma once
/// @file Front end for one triangle: cull, clip, snap, split into screen triangles, reject small ones.
#include <cstdint>
#include <vector>

#include "render/raster_triangle.hpp"
#include "render/view_projection.hpp"

namespace silva::render {

/// One mesh triangle in view space with what the rasteriser needs to know about its part.
struct TriangleInput {
  Vec3d p[3];                       ///< View-space vertices in mesh order.
  const Vec2f* uv[3] = {};          ///< Vertex uvs (only read when mask is set).
  const AlphaMask* mask = nullptr;  ///< Alpha mask of the part, or null.
  bool cull_back = true;            ///< Drop the triangle when it faces away.
  bool inside_view = false;         ///< Known inside every frustum plane: skip the frustum and clip tests.
  uint64_t key = 0;                 ///< instance << 32 | triangle index.
};

/// Per-thread counters of the front end.
struct SetupCounters {
  uint64_t after_cull = 0;  ///< Triangles that survived frustum and back-face culling.
  uint64_t clipped = 0;     ///< Triangles that needed clipping.
  uint64_t emitted = 0;     ///< Screen triangles appended.
};

/// A view plus its planes, prepared once per pass.
struct SetupView {
  ViewProjection view;   ///< The view.
  Vec4d frustum[6];      ///< Trivial-reject planes.
  int frustum_count = 0; ///< Number of frustum planes.
  Vec4d clip[5];         ///< Clip planes (near, guard band).
  int clip_count = 0;    ///< Number of clip planes.
  /// Prepares the planes of a view.
  explicit SetupView(const ViewProjection& v);
};

/// Sets up one triangle: appends 0 or more RasterTris to `tris` (and one AlphaAttrib to
/// `alphas` when masked and visible). Returns the number of RasterTris appended.
int setup_triangle(const SetupView& sv, const TriangleInput& in, std::vector<RasterTri>& tris,
                   std::vector<AlphaAttrib>& alphas, SetupCounters& counters);

}  // namespace silva::render
