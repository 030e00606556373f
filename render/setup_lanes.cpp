// The per-target kernel is compiled once per Highway target (foreach_target) and chosen at run
// time. Every lane repeats setup_triangle's operations in its order with correctly rounded
// operations only (no MulAdd); snapped coordinates and edge values are integers below 2^53 held in
// doubles, so integer and double arithmetic agree exactly.
#include "render/setup_lanes.hpp"

#include <algorithm>

#include "render/raster_conventions.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/setup_lanes.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace silva::render::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

using DTag = hn::ScalableTag<double>;
/// Most lanes of any target.
constexpr size_t kMaxLanes = hn::MaxLanes(DTag());
/// A pixel centre's offset inside its pixel, in sub-pixel units (128).
constexpr double kHalfPixel = 0.5 * double(kSubpixelScale);

/// Lane arrays of one group of triangles: inputs, then the set-up results.
struct Lanes {
  HWY_ALIGN double p[3][3][kMaxLanes];   ///< View-space position [vertex][axis].
  HWY_ALIGN double s[3][2][kMaxLanes];   ///< Snapped screen position [vertex][axis], 1/256 pixel.
  HWY_ALIGN double vd[3][kMaxLanes];     ///< Reverse depth of each vertex.
  HWY_ALIGN double uv[3][2][kMaxLanes];  ///< Texture coordinates [vertex][axis] (masked parts).
  HWY_ALIGN double edge[3][3][kMaxLanes];  ///< Edge functions [edge][c, dx, dy].
  HWY_ALIGN double depth[3][kMaxLanes];  ///< Depth plane c, a, b.
  HWY_ALIGN double depth_max[kMaxLanes]; ///< Conservative maximum depth.
  HWY_ALIGN double box[4][kMaxLanes];    ///< x0, y0, x1, y1.
  HWY_ALIGN double tex[3][3][kMaxLanes]; ///< Alpha planes [u, v, w][c, a, b].
  uint8_t after_cull[8];                 ///< Mask bits: survived the facing tests.
  uint8_t keep[8];                       ///< Mask bits: emits a screen triangle.
};

/// A 3-vector of lanes.
template <class V>
struct V3 {
  V x, y, z;  ///< Components.
};

/// cross3 on lanes.
template <class V>
V3<V> cross_lanes(const V3<V>& a, const V3<V>& b) {
  return {hn::Sub(hn::Mul(a.y, b.z), hn::Mul(a.z, b.y)), hn::Sub(hn::Mul(a.z, b.x), hn::Mul(a.x, b.z)),
          hn::Sub(hn::Mul(a.x, b.y), hn::Mul(a.y, b.x))};
}

/// dot3 on lanes.
template <class V>
V dot_lanes(const V3<V>& a, const V3<V>& b) {
  return hn::Add(hn::Add(hn::Mul(a.x, b.x), hn::Mul(a.y, b.y)), hn::Mul(a.z, b.z));
}

/// Stores to_pixel_plane(c, a, b) of every lane into out[0..2].
template <class D, class V>
void store_pixel_plane(D d, V c, V a, V b, double (*out)[kMaxLanes]) {
  const auto half = hn::Set(d, 0.5);
  hn::Store(hn::Add(hn::Add(c, hn::Mul(half, a)), hn::Mul(half, b)), d, out[0]);
  hn::Store(a, d, out[1]);
  hn::Store(b, d, out[2]);
}

/// Edge function a -> b of every lane (triangle_setup.cpp's edge_function) into out[c, dx, dy];
/// returns whether pixel (px, py) is inside it.
template <class D, class V>
auto edge_lanes(D d, V ax, V ay, V bx, V by, V px, V py, double (*out)[kMaxLanes]) {
  const auto zero = hn::Zero(d), half = hn::Set(d, kHalfPixel), scale = hn::Set(d, double(kSubpixelScale));
  const auto dx = hn::Sub(bx, ax), dy = hn::Sub(by, ay);
  const auto top_left = hn::Or(hn::Lt(dy, zero), hn::And(hn::Eq(dy, zero), hn::Gt(dx, zero)));
  const auto c = hn::Sub(hn::Sub(hn::Mul(dx, hn::Sub(half, ay)), hn::Mul(dy, hn::Sub(half, ax))),
                         hn::IfThenZeroElse(top_left, hn::Set(d, 1.0)));
  hn::Store(c, d, out[0]);
  hn::Store(dx, d, out[1]);
  hn::Store(dy, d, out[2]);
  const auto at = hn::Add(hn::Add(c, hn::Mul(hn::Mul(scale, dx), py)), hn::Mul(hn::Neg(hn::Mul(scale, dy)), px));
  return hn::Ge(at, zero);
}

/// Lanes of `alive` whose triangle (p0, p1, p2) is not wholly behind one of sv's frustum planes
/// (setup_triangle's trivial reject, plane values in its order).
template <class D, class V, class M>
M in_frustum(D d, const SetupView& sv, const V3<V>& p0, const V3<V>& p1, const V3<V>& p2, M alive) {
  const auto zero = hn::Zero(d);
  for (int k = 0; k < sv.frustum_count; ++k) {
    const Vec4d& pl = sv.frustum[k];
    const auto behind = [&](const V3<V>& p) {
      const auto v = hn::Add(hn::Add(hn::Add(hn::Mul(hn::Set(d, pl.x()), p.x), hn::Mul(hn::Set(d, pl.y()), p.y)),
                                     hn::Mul(hn::Set(d, pl.z()), p.z)),
                             hn::Set(d, pl.w()));
      return hn::Lt(v, zero);
    };
    alive = hn::AndNot(hn::And(behind(p0), hn::And(behind(p1), behind(p2))), alive);
  }
  return alive;
}

/// Alpha planes of every lane into L.tex (ViewProjection::barycentric_planes, then
/// triangle_setup.cpp's texcoord_plane), from vertex 0 and the edges e1 = p1 - p0, e2 = p2 - p0.
template <class D, class V>
HWY_INLINE void store_alpha_planes(D d, const PixelScales& sc, const V3<V>& p0, const V3<V>& e1, const V3<V>& e2,
                                   Lanes& L) {
  const V3<V> o{hn::Neg(p0.x), hn::Neg(p0.y), hn::Neg(p0.z)};
  const auto q1 = cross_lanes(e2, o), q2 = cross_lanes(o, e1), qd = cross_lanes(e2, e1);
  HWY_ALIGN double bary[3][3][kMaxLanes];  // n1, n2, den
  const V3<V>* qs[3] = {&q1, &q2, &qd};
  for (int k = 0; k < 3; ++k) {
    const auto& q = *qs[k];
    const auto a = hn::Mul(q.x, hn::Set(d, sc.inv_fx)), b = hn::Mul(q.y, hn::Set(d, sc.inv_fy));
    store_pixel_plane(d, hn::Sub(hn::Sub(q.z, hn::Mul(q.x, hn::Set(d, sc.cx_fx))), hn::Mul(q.y, hn::Set(d, sc.cy_fy))), a, b, bary[k]);
  }
  for (int axis = 0; axis < 2; ++axis) {
    const auto t0 = hn::Load(d, L.uv[0][axis]);
    const auto k1 = hn::Sub(hn::Load(d, L.uv[1][axis]), t0), k2 = hn::Sub(hn::Load(d, L.uv[2][axis]), t0);
    for (int f = 0; f < 3; ++f)
      hn::Store(hn::Add(hn::Add(hn::Mul(t0, hn::Load(d, bary[2][f])), hn::Mul(k1, hn::Load(d, bary[0][f]))),
                        hn::Mul(k2, hn::Load(d, bary[1][f]))),
                d, L.tex[axis][f]);
  }
  for (int f = 0; f < 3; ++f) hn::Store(hn::Load(d, bary[2][f]), d, L.tex[2][f]);
}

/// Sets up the lanes of one group (inputs filled): every result array and the two masks; with
/// `frustum_test`, triangles wholly behind a frustum plane are dropped first (not counted).
void setup_group(const SetupView& sv, bool cull_back, bool masked, bool frustum_test, size_t n, Lanes& L) {
  const DTag d;
  const ViewProjection& view = sv.view;
  const PixelScales& sc = sv.scales;
  const auto load3 = [&](int v) { return V3<hn::Vec<DTag>>{hn::Load(d, L.p[v][0]), hn::Load(d, L.p[v][1]), hn::Load(d, L.p[v][2])}; };
  const auto p0 = load3(0), p1 = load3(1), p2 = load3(2);
  auto finite = hn::FirstN(d, n);
  for (const auto* p : {&p0, &p1, &p2}) finite = hn::And(finite, hn::And(hn::IsFinite(p->x), hn::And(hn::IsFinite(p->y), hn::IsFinite(p->z))));
  if (frustum_test) finite = in_frustum(d, sv, p0, p1, p2, finite);
  const auto sub3 = [](const auto& a, const auto& b) { return V3<hn::Vec<DTag>>{hn::Sub(a.x, b.x), hn::Sub(a.y, b.y), hn::Sub(a.z, b.z)}; };
  const auto e1 = sub3(p1, p0), e2 = sub3(p2, p0);
  const auto nrm = cross_lanes(e1, e2);
  const auto facing = dot_lanes(p0, nrm);
  const auto zero = hn::Zero(d);
  const auto front = hn::Lt(facing, zero);
  auto alive = hn::And(finite, hn::And(hn::Ne(facing, zero), hn::IsFinite(facing)));
  if (cull_back) alive = hn::And(alive, front);
  hn::StoreMaskBits(d, alive, L.after_cull);

  // Snapped vertices; front faces swap b and c so that the drawn area is positive.
  const auto ax = hn::Load(d, L.s[0][0]), ay = hn::Load(d, L.s[0][1]);
  const auto s1x = hn::Load(d, L.s[1][0]), s1y = hn::Load(d, L.s[1][1]);
  const auto s2x = hn::Load(d, L.s[2][0]), s2y = hn::Load(d, L.s[2][1]);
  const auto area = hn::Sub(hn::Mul(hn::Sub(s1x, ax), hn::Sub(s2y, ay)), hn::Mul(hn::Sub(s1y, ay), hn::Sub(s2x, ax)));
  // A front face needs A < 0 before the swap, a back face A > 0 (snapping can flip slivers).
  const auto area_ok = hn::Or(hn::And(front, hn::Lt(area, zero)), hn::AndNot(front, hn::Gt(area, zero)));
  auto keep = hn::And(alive, area_ok);
  const auto bx = hn::IfThenElse(front, s2x, s1x), by = hn::IfThenElse(front, s2y, s1y);
  const auto cx = hn::IfThenElse(front, s1x, s2x), cy = hn::IfThenElse(front, s1y, s2y);

  // Candidate pixels: floor((min - 128 + 255) / 256) .. floor((max - 128) / 256), clamped to the image.
  const auto inv_scale = hn::Set(d, 1.0 / double(kSubpixelScale)), half = hn::Set(d, kHalfPixel);
  const auto first_px = [&](auto lo) { return hn::Max(zero, hn::Floor(hn::Mul(hn::Add(hn::Sub(lo, half), hn::Set(d, double(kSubpixelScale - 1))), inv_scale))); };
  const auto last_px = [&](auto hi, int size) { return hn::Min(hn::Set(d, double(size - 1)), hn::Floor(hn::Mul(hn::Sub(hi, half), inv_scale))); };
  const auto x0 = first_px(hn::Min(hn::Min(ax, bx), cx)), y0 = first_px(hn::Min(hn::Min(ay, by), cy));
  const auto x1 = last_px(hn::Max(hn::Max(ax, bx), cx), view.width), y1 = last_px(hn::Max(hn::Max(ay, by), cy), view.height);
  keep = hn::And(keep, hn::And(hn::Le(x0, x1), hn::Le(y0, y1)));
  hn::Store(x0, d, L.box[0]);
  hn::Store(y0, d, L.box[1]);
  hn::Store(x1, d, L.box[2]);
  hn::Store(y1, d, L.box[3]);
  const auto in0 = edge_lanes(d, ax, ay, bx, by, x0, y0, L.edge[0]);
  const auto in1 = edge_lanes(d, bx, by, cx, cy, x0, y0, L.edge[1]);
  const auto in2 = edge_lanes(d, cx, cy, ax, ay, x0, y0, L.edge[2]);
  const auto single = hn::And(hn::Eq(x0, x1), hn::Eq(y0, y1));
  keep = hn::AndNot(hn::AndNot(hn::And(in0, hn::And(in1, in2)), single), keep);
  hn::StoreMaskBits(d, keep, L.keep);

  // Depth plane (ViewProjection::depth_plane) and its conservative maximum.
  const auto inv_k = hn::Div(hn::Set(d, 1.0), facing);
  const auto dc = hn::Mul(hn::Sub(hn::Sub(nrm.z, hn::Mul(nrm.x, hn::Set(d, sc.cx_fx))), hn::Mul(nrm.y, hn::Set(d, sc.cy_fy))), inv_k);
  const auto da = hn::Mul(hn::Mul(nrm.x, hn::Set(d, sc.inv_fx)), inv_k);
  const auto db = hn::Mul(hn::Mul(nrm.y, hn::Set(d, sc.inv_fy)), inv_k);
  store_pixel_plane(d, dc, da, db, L.depth);
  const auto pc = hn::Load(d, L.depth[0]);
  const auto vmax = hn::Max(hn::Max(hn::Load(d, L.vd[0]), hn::Load(d, L.vd[1])), hn::Load(d, L.vd[2]));
  const auto span = hn::Add(hn::Add(hn::Abs(pc), hn::Mul(hn::Abs(da), hn::Set(d, double(view.width)))),
                            hn::Mul(hn::Abs(db), hn::Set(d, double(view.height))));
  hn::Store(hn::Add(hn::Add(hn::Add(vmax, hn::Abs(da)), hn::Abs(db)), hn::Mul(hn::Set(d, 1e-9), hn::Add(span, hn::Abs(vmax)))), d,
            L.depth_max);
  if (masked) store_alpha_planes(d, sc, p0, e1, e2, L);
}

/// setup_triangles_lanes for one target.
void SetupTrianglesImpl(const SetupView& sv, const LaneTriangles& in, const TileGrid& grid, GeometryStore& store) {
  const size_t N = hn::Lanes(DTag());
  Lanes L;
  const bool masked = in.mask != nullptr;
  const uint32_t end = in.first + in.count;
  for (uint32_t first = in.first; first < end; first += uint32_t(N)) {
    const size_t n = std::min<size_t>(N, end - first);
    for (size_t k = 0; k < N; ++k) {
      const size_t t = first + std::min(k, n - 1);  // the tail repeats the last triangle
      for (int j = 0; j < 3; ++j) {
        const uint32_t vi = in.indices[t * 3 + size_t(j)];
        const SetupVertex& v = in.vertices[vi];
        for (int a = 0; a < 3; ++a) L.p[j][a][k] = v.p[a];
        L.s[j][0][k] = double(v.x);
        L.s[j][1][k] = double(v.y);
        L.vd[j][k] = v.depth;
        if (masked) {
          L.uv[j][0][k] = double(in.uvs[vi].x());
          L.uv[j][1][k] = double(in.uvs[vi].y());
        }
      }
    }
    setup_group(sv, in.cull_back, masked, in.frustum_test, n, L);
    for (size_t k = 0; k < n; ++k) {
      store.counters.after_cull += (L.after_cull[k / 8] >> (k % 8)) & 1u;
      if (!((L.keep[k / 8] >> (k % 8)) & 1u)) continue;
      uint32_t alpha = kNoAlpha;
      if (masked) {
        alpha = uint32_t(store.alphas.size());
        AlphaAttrib& at = store.alphas.emplace_back();
        at.u = PixelPlane{L.tex[0][0][k], L.tex[0][1][k], L.tex[0][2][k]};
        at.v = PixelPlane{L.tex[1][0][k], L.tex[1][1][k], L.tex[1][2][k]};
        at.w = PixelPlane{L.tex[2][0][k], L.tex[2][1][k], L.tex[2][2][k]};
        at.bits = in.mask;
      }
      const auto edge = [&](int e) { return EdgeFunction{L.edge[e][0][k], int32_t(L.edge[e][1][k]), int32_t(L.edge[e][2][k])}; };
      const uint32_t index = uint32_t(store.tris.size());
      store.tris.push_back(RasterTri{{edge(0), edge(1), edge(2)},
                                     PixelPlane{L.depth[0][k], L.depth[1][k], L.depth[2][k]},
                                     in.key_base | (first + k),
                                     alpha});
      ++store.counters.emitted;
      store.bin(index,
                TriBounds{int32_t(L.box[0][k]), int32_t(L.box[1][k]), int32_t(L.box[2][k]), int32_t(L.box[3][k]), L.depth_max[k]},
                grid);
    }
  }
}

/// The target this copy of the kernel was compiled for.
int64_t SetupTargetImpl() { return HWY_TARGET; }

}  // namespace silva::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace silva::render {

HWY_EXPORT(SetupTrianglesImpl);
HWY_EXPORT(SetupTargetImpl);

void setup_triangles_lanes(const SetupView& sv, const LaneTriangles& in, const TileGrid& grid, GeometryStore& store) {
  HWY_DYNAMIC_DISPATCH(SetupTrianglesImpl)(sv, in, grid, store);
}

int64_t setup_simd_target() { return HWY_DYNAMIC_DISPATCH(SetupTargetImpl)(); }

}  // namespace silva::render
#endif  // HWY_ONCE
