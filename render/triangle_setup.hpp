#pragma once
/// @file Front end for one triangle: cull, clip, snap, split into screen triangles, reject small ones.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "render/clip.hpp"
#include "render/raster_triangle.hpp"
#include "render/view_projection.hpp"

namespace silva::render {

/// A view-space vertex and, once a triangle that needs no clipping has used it, its snapped
/// screen position: computed once per vertex and geometry item instead of once per triangle.
struct SetupVertex {
  Vec3d p;                 ///< View-space position.
  bool projected = false;  ///< x, y and depth are set.
  int64_t x = 0, y = 0;    ///< Screen position in 1/256 pixel, rounded (raster_conventions.hpp).
  double depth = 0;        ///< Reverse depth value of p.
};

/// View-space position of a mesh vertex: m * (p, 1) in double.
inline Vec3d to_view(const Eigen::Matrix<double, 3, 4>& m, const Vec3f& p) {
  return Vec3d(m.leftCols<3>() * p.cast<double>() + m.col(3));
}

/// Sets v's snapped screen position and reverse depth from v.p (in front of the camera when the
/// view is a perspective one) and marks it projected.
void project_vertex(const ViewProjection& view, SetupVertex& v);

/// Per-worker SetupVertex slots indexed by mesh vertex, valid for the current geometry item only.
struct VertexCache {
  std::vector<SetupVertex> slots;  ///< One per mesh vertex.
  std::vector<uint32_t> stamp;     ///< Item number that last filled each slot.
  uint32_t item = 0;               ///< Current item number.
  /// Starts a new item over a mesh of `vertex_count` vertices (every slot becomes stale).
  void begin_item(size_t vertex_count) {
    if (slots.size() < vertex_count) {
      slots.resize(vertex_count);
      stamp.resize(vertex_count, 0);
    }
    if (++item == 0) {  // wrapped: forget every stamp
      std::fill(stamp.begin(), stamp.end(), 0u);
      item = 1;
    }
  }
  /// Slots of vertices [first, first + count) (inside the item's vertex count), marked as filled
  /// for the current item: the caller fills them.
  SetupVertex* fill(uint32_t first, uint32_t count) {
    std::fill(stamp.begin() + first, stamp.begin() + first + count, item);
    return slots.data() + first;
  }
  /// Slot of vertex `index` (< the item's vertex count); `position()` gives its view-space
  /// position on first use in this item.
  template <class Position>
  SetupVertex& get(uint32_t index, Position&& position) {
    SetupVertex& v = slots[index];
    if (stamp[index] != item) {
      stamp[index] = item;
      v.p = position();
      v.projected = false;
    }
    return v;
  }
};

/// One mesh triangle in view space with what the rasteriser needs to know about its part.
struct TriangleInput {
  SetupVertex* v[3] = {};           ///< View-space vertices in mesh order (shared between triangles).
  const Vec2f* uv[3] = {};          ///< Vertex uvs (only read when mask is set).
  const AlphaBits* mask = nullptr;  ///< Opacity bits of the part's alpha mask, or null.
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
  PixelScales scales;    ///< view.pixel_scales().
  /// Prepares the planes of a view.
  explicit SetupView(const ViewProjection& v);
};

/// Most screen triangles one mesh triangle can become (the fan of its clipped polygon).
inline constexpr int kMaxSetupTriangles = kMaxClippedVertices - 2;

/// Sets up one triangle: appends 0 or more RasterTris to `tris` (and one AlphaAttrib to
/// `alphas` when masked and visible) and writes the bounds of each to `bounds[0..n)`. Returns the
/// number n of RasterTris appended. A triangle that needs no clipping stores its vertices'
/// snapped positions in them (SetupVertex::projected) for the next triangles sharing them.
int setup_triangle(const SetupView& sv, const TriangleInput& in, std::vector<RasterTri>& tris,
                   std::vector<AlphaAttrib>& alphas, TriBounds (&bounds)[kMaxSetupTriangles], SetupCounters& counters);

}  // namespace silva::render
