#include "render/triangle_setup.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/det_math.hpp"
#include "render/clip.hpp"
#include "render/raster_conventions.hpp"

namespace silva::render {

namespace {

/// A vertex snapped to the sub-pixel grid (no member initialisers: the setup's arrays of them
/// are filled before use, and zeroing them showed in profiles).
struct Snapped {
  int64_t x;  ///< u * 256, rounded.
  int64_t y;  ///< v * 256, rounded.
};

/// Offset of a pixel centre inside its pixel, in sub-pixel units.
constexpr int64_t kHalf = kSubpixelScale / 2;

/// Floor of a / b for b > 0.
int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

/// Screen position of a view-space point (inside the near plane) snapped to the sub-pixel grid.
Snapped snap(const ViewProjection& view, const Vec3d& p) {
  const Vec2d uv = view.project(p);
  return Snapped{round_half_away(uv.x() * double(kSubpixelScale)), round_half_away(uv.y() * double(kSubpixelScale))};
}

/// Value of a plane at a point.
double plane_value(const Vec4d& plane, const Vec3d& p) {
  return plane.x() * p.x() + plane.y() * p.y() + plane.z() * p.z() + plane.w();
}

/// Edge function of a->b (A > 0 orientation) with its fill-rule bias, over pixel indices.
EdgeFunction edge_function(const Snapped& a, const Snapped& b) {
  const int64_t dx = b.x - a.x, dy = b.y - a.y;
  const bool top_left = dy < 0 || (dy == 0 && dx > 0);
  const int64_t c = dx * (kHalf - a.y) - dy * (kHalf - a.x) - (top_left ? 0 : 1);
  return EdgeFunction{double(c), int32_t(dx), int32_t(dy)};
}

/// True when all three (exact) edge values are inside at pixel (x, y).
bool covers(const EdgeFunction (&edge)[3], int x, int y) {
  for (const EdgeFunction& e : edge)
    if (e.at(double(x), double(y)) < 0.0) return false;
  return true;
}

/// Plane of the texture coordinate times den, t0 den + (t1 - t0) n1 + (t2 - t0) n2, from the
/// barycentric planes (b1 = n1 / den, b2 = n2 / den) and the coordinate at the three vertices.
PixelPlane texcoord_plane(const PixelPlane& n1, const PixelPlane& n2, const PixelPlane& den, float t0, float t1, float t2) {
  const double k0 = t0, k1 = double(t1) - double(t0), k2 = double(t2) - double(t0);
  const auto mix = [&](double d, double x1, double x2) { return (k0 * d + k1 * x1) + k2 * x2; };
  return PixelPlane{mix(den.c, n1.c, n2.c), mix(den.a, n1.a, n2.a), mix(den.b, n1.b, n2.b)};
}

/// Lazily computed per-source-triangle data shared by its screen triangles.
struct SharedPlanes {
  bool ready = false;       ///< Planes computed.
  PixelPlane depth;         ///< Reverse-depth plane.
  double depth_max = 0;     ///< Conservative maximum of d.
  uint32_t alpha = kNoAlpha;  ///< AlphaAttrib index.
};

/// Fills `shared` for the source triangle `in` (face normal n): its depth plane, the conservative
/// maximum of depth over it, and for masked parts its alpha planes (appended to `alphas`).
void compute_shared_planes(const SetupView& sv, const TriangleInput& in, const Vec3d& n, double vertex_depth_max,
                           std::vector<AlphaAttrib>& alphas, SharedPlanes& shared) {
  const ViewProjection& view = sv.view;
  const Vec3d& p0 = in.v[0]->p;
  shared.ready = true;
  shared.depth = view.depth_plane(p0, n, sv.scales);
  const PixelPlane& d = shared.depth;
  const double span = std::abs(d.c) + std::abs(d.a) * double(view.width) + std::abs(d.b) * double(view.height);
  shared.depth_max = vertex_depth_max + std::abs(d.a) + std::abs(d.b) + 1e-9 * (span + std::abs(vertex_depth_max));
  if (!in.mask) return;
  shared.alpha = uint32_t(alphas.size());
  AlphaAttrib& at = alphas.emplace_back();
  PixelPlane n1, n2;
  view.barycentric_planes(p0, in.v[1]->p, in.v[2]->p, sv.scales, n1, n2, at.w);
  const Vec2f &uv0 = *in.uv[0], &uv1 = *in.uv[1], &uv2 = *in.uv[2];
  at.u = texcoord_plane(n1, n2, at.w, uv0.x(), uv1.x(), uv2.x());
  at.v = texcoord_plane(n1, n2, at.w, uv0.y(), uv1.y(), uv2.y());
  at.bits = in.mask;
}

}  // namespace

void project_vertex(const ViewProjection& view, SetupVertex& v) {
  const Snapped sn = snap(view, v.p);
  v.x = sn.x;
  v.y = sn.y;
  v.depth = view.depth_value(v.p);
  v.projected = true;
}

SetupView::SetupView(const ViewProjection& v) : view(v) {
  frustum_count = view.frustum_planes(frustum);
  clip_count = view.clip_planes(clip);
  scales = view.pixel_scales();
}

int setup_triangle(const SetupView& sv, const TriangleInput& in, std::vector<RasterTri>& tris,
                   std::vector<AlphaAttrib>& alphas, TriBounds (&bounds)[kMaxSetupTriangles], SetupCounters& counters) {
  const ViewProjection& view = sv.view;
  const Vec3d& p0 = in.v[0]->p;
  const Vec3d& p1 = in.v[1]->p;
  const Vec3d& p2 = in.v[2]->p;
  if (!(p0.allFinite() && p1.allFinite() && p2.allFinite())) return 0;
  for (int k = in.inside_view ? sv.frustum_count : 0; k < sv.frustum_count; ++k) {
    const Vec4d& pl = sv.frustum[k];
    if (plane_value(pl, p0) < 0.0 && plane_value(pl, p1) < 0.0 && plane_value(pl, p2) < 0.0) return 0;
  }
  const Vec3d n = cross3(p1 - p0, p2 - p0);
  const double facing = view.facing(p0, n);
  if (!(facing != 0.0) || !std::isfinite(facing)) return 0;  // edge-on, degenerate or NaN
  const bool front = facing < 0.0;
  if (!front && in.cull_back) return 0;
  ++counters.after_cull;

  bool needs_clip = false;
  for (int k = in.inside_view ? sv.clip_count : 0; k < sv.clip_count && !needs_clip; ++k)
    needs_clip = plane_value(sv.clip[k], p0) < 0.0 || plane_value(sv.clip[k], p1) < 0.0 ||
                 plane_value(sv.clip[k], p2) < 0.0;
  Snapped s[kMaxClippedVertices];
  double vertex_depth_max = -std::numeric_limits<double>::infinity();
  int count = 3;
  if (needs_clip) {
    ++counters.clipped;
    Vec3d poly[kMaxClippedVertices] = {p0, p1, p2};
    count = clip_polygon(sv.clip, sv.clip_count, poly, count);
    if (count == 0) return 0;
    for (int i = 0; i < count; ++i) {
      s[i] = snap(view, poly[i]);
      vertex_depth_max = std::max(vertex_depth_max, view.depth_value(poly[i]));
    }
  } else {
    for (int i = 0; i < 3; ++i) {
      SetupVertex& v = *in.v[i];
      if (!v.projected) project_vertex(view, v);
      s[i] = Snapped{v.x, v.y};
      vertex_depth_max = std::max(vertex_depth_max, v.depth);
    }
  }

  SharedPlanes shared;
  int emitted = 0;
  for (int k = 1; k + 1 < count; ++k) {
    Snapped a = s[0], b = s[k], c = s[k + 1];
    const int64_t area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (front) {
      if (area >= 0) continue;  // sliver flipped by snapping
      std::swap(b, c);
    } else if (area <= 0) {
      continue;
    }
    // Pixels whose centres may be covered: the bounding box of the snapped vertices.
    const int64_t min_x = std::min({a.x, b.x, c.x}), max_x = std::max({a.x, b.x, c.x});
    const int64_t min_y = std::min({a.y, b.y, c.y}), max_y = std::max({a.y, b.y, c.y});
    const int64_t x0 = std::max<int64_t>(0, floor_div(min_x - kHalf + kSubpixelScale - 1, kSubpixelScale));
    const int64_t y0 = std::max<int64_t>(0, floor_div(min_y - kHalf + kSubpixelScale - 1, kSubpixelScale));
    const int64_t x1 = std::min<int64_t>(view.width - 1, floor_div(max_x - kHalf, kSubpixelScale));
    const int64_t y1 = std::min<int64_t>(view.height - 1, floor_div(max_y - kHalf, kSubpixelScale));
    if (x0 > x1 || y0 > y1) continue;  // covers no sample centre
    const EdgeFunction edge[3] = {edge_function(a, b), edge_function(b, c), edge_function(c, a)};
    if (x0 == x1 && y0 == y1 && !covers(edge, int(x0), int(y0))) continue;  // one candidate, missed
    if (!shared.ready) compute_shared_planes(sv, in, n, vertex_depth_max, alphas, shared);
    tris.push_back(RasterTri{{edge[0], edge[1], edge[2]}, shared.depth, in.key, shared.alpha});
    bounds[emitted++] = TriBounds{int32_t(x0), int32_t(y0), int32_t(x1), int32_t(y1), shared.depth_max};
  }
  counters.emitted += uint64_t(emitted);
  return emitted;
}

}  // namespace silva::render
