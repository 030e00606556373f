// hit_geometry_run on Highway lanes, one pixel per lane: the per-target kernel is compiled once per
// Highway target (foreach_target) and chosen at run time. Only correctly rounded double operations in
// hit_geometry's order (no MulAdd), rounded to float at the end, so every target gives its bits.
#include <algorithm>

#include "render/hit_geometry.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/hit_geometry_lanes.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace silva::render::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

/// Double lanes: one pixel per lane.
using DTag = hn::ScalableTag<double>;
/// A vector of double lanes.
using VD = hn::Vec<DTag>;

/// Three double vectors: a 3-vector per lane.
struct V3 {
  VD x, y, z;  ///< Components.
};

/// a . b as Eigen sums a fixed 3-vector dot product: (a0 b0 + a1 b1) + a2 b2.
HWY_INLINE VD dot(const V3& a, const V3& b) {
  return hn::Add(hn::Add(hn::Mul(a.x, b.x), hn::Mul(a.y, b.y)), hn::Mul(a.z, b.z));
}

/// The same vector `v` on every lane.
HWY_INLINE V3 splat(const Vec3d& v) {
  const DTag d;
  return {hn::Set(d, v.x()), hn::Set(d, v.y()), hn::Set(d, v.z())};
}

/// m v for the top-left 3x3 of a matrix the same on every lane, as Eigen's fixed-size product associates:
/// rows 0 and 1 left to right, row 2 as m20 v0 + (m21 v1 + m22 v2).
template <class M>
HWY_INLINE V3 product(const M& m, const V3& v) {
  const DTag d;
  const auto row01 = [&](int r) {
    return hn::Add(hn::Add(hn::Mul(hn::Set(d, m(r, 0)), v.x), hn::Mul(hn::Set(d, m(r, 1)), v.y)),
                   hn::Mul(hn::Set(d, m(r, 2)), v.z));
  };
  return {row01(0), row01(1),
          hn::Add(hn::Mul(hn::Set(d, m(2, 0)), v.x), hn::Add(hn::Mul(hn::Set(d, m(2, 1)), v.y), hn::Mul(hn::Set(d, m(2, 2)), v.z)))};
}

/// b0 c0 + b1 c1 + b2 c2, left to right, for corners c the same on every lane.
template <class C>
HWY_INLINE VD blend(VD b0, VD b1, VD b2, const C& c0, const C& c1, const C& c2, int k) {
  const DTag d;
  return hn::Add(hn::Add(hn::Mul(b0, hn::Set(d, c0[k])), hn::Mul(b1, hn::Set(d, c1[k]))), hn::Mul(b2, hn::Set(d, c2[k])));
}

/// The lanes of hit_geometry for the rays in x (ray_y fixed): depth t, hit, unit normal facing the camera,
/// uv; `fallback` gets the lanes that take one of hit_geometry's fallbacks.
struct LaneHit {
  VD t;                    ///< Metric z.
  V3 hit, n;               ///< World position and normal.
  VD u, v;                 ///< uv.
  hn::Mask<DTag> fallback; ///< Lanes whose values are not hit_geometry's.
};

/// Evaluates hit_geometry's common path on the lanes of x.
HWY_INLINE LaneHit hit_lanes(const Camera& cam, const HitGeometry& h, VD x, double ray_y) {
  const DTag d;
  const V3 dir = product(cam.camera_to_world, V3{x, hn::Set(d, ray_y), hn::Set(d, 1.0)});  // Camera::world_direction
  const V3 e1 = splat(h.e1), e2 = splat(h.e2);
  const V3 pvec{hn::Sub(hn::Mul(dir.y, e2.z), hn::Mul(dir.z, e2.y)), hn::Sub(hn::Mul(dir.z, e2.x), hn::Mul(dir.x, e2.z)),
                hn::Sub(hn::Mul(dir.x, e2.y), hn::Mul(dir.y, e2.x))};
  const VD det = dot(e1, pvec);
  const VD b1 = hn::Div(dot(splat(h.s), pvec), det);
  const VD b2 = hn::Div(dot(dir, splat(h.qvec)), det);
  LaneHit out;
  out.t = hn::Div(hn::Set(d, h.e2_dot_q), det);
  out.fallback = hn::Or(hn::Eq(det, hn::Zero(d)), hn::Not(hn::Gt(out.t, hn::Zero(d))));
  const VD b0 = hn::Sub(hn::Sub(hn::Set(d, 1.0), b1), b2);
  const Vec3d origin = cam.position();
  out.hit = {hn::Add(hn::Set(d, origin.x()), hn::Mul(out.t, dir.x)), hn::Add(hn::Set(d, origin.y()), hn::Mul(out.t, dir.y)),
             hn::Add(hn::Set(d, origin.z()), hn::Mul(out.t, dir.z))};
  const auto& cn = h.corner_normal;
  V3 n = h.has_normals ? product(h.cof, V3{blend(b0, b1, b2, cn[0], cn[1], cn[2], 0), blend(b0, b1, b2, cn[0], cn[1], cn[2], 1),
                                          blend(b0, b1, b2, cn[0], cn[1], cn[2], 2)})
                       : splat(h.e1.cross(h.e2));
  const VD len = hn::Sqrt(dot(n, n));
  out.fallback = hn::Or(out.fallback, hn::Not(hn::Gt(len, hn::Zero(d))));
  n = {hn::Div(n.x, len), hn::Div(n.y, len), hn::Div(n.z, len)};
  const auto facing_away = hn::Gt(dot(n, dir), hn::Zero(d));
  out.n = {hn::IfThenElse(facing_away, hn::Neg(n.x), n.x), hn::IfThenElse(facing_away, hn::Neg(n.y), n.y),
           hn::IfThenElse(facing_away, hn::Neg(n.z), n.z)};
  out.u = out.v = hn::Zero(d);
  if (h.has_uvs) {
    const auto& cu = h.corner_uv;
    out.u = blend(b0, b1, b2, cu[0], cu[1], cu[2], 0);
    out.v = blend(b0, b1, b2, cu[0], cu[1], cu[2], 1);
  }
  return out;
}

/// hit_geometry_run for one target.
uint64_t HitGeometryRunImpl(const Camera& cam, const HitGeometry& h, const double* ray_x, double ray_y, size_t count,
                            float* depth, Vec3f* position, Vec3f* normal, Vec2f* uv, float* mask_texels) {
  const DTag d;
  const hn::Rebind<float, DTag> df;
  const size_t N = hn::Lanes(d);
  const VD texels_per_metre = hn::Set(d, h.mask_texels_per_metre), fx = hn::Set(d, cam.fx);
  HWY_ALIGN double x_in[hn::MaxLanes(d)];
  HWY_ALIGN float t_out[hn::MaxLanes(d)], p_out[3 * hn::MaxLanes(d)], n_out[3 * hn::MaxLanes(d)],
      uv_out[2 * hn::MaxLanes(d)], m_out[hn::MaxLanes(d)];
  uint8_t bits[8] = {};
  uint64_t fallback = 0;
  for (size_t k = 0; k < count; k += N) {
    const size_t n = std::min(N, count - k);
    std::fill(std::copy(ray_x + k, ray_x + k + n, x_in), x_in + N, ray_x[k]);
    const LaneHit lanes = hit_lanes(cam, h, hn::Load(d, x_in), ray_y);
    hn::Store(hn::DemoteTo(df, lanes.t), df, t_out);
    hn::StoreInterleaved3(hn::DemoteTo(df, lanes.hit.x), hn::DemoteTo(df, lanes.hit.y), hn::DemoteTo(df, lanes.hit.z), df, p_out);
    hn::StoreInterleaved3(hn::DemoteTo(df, lanes.n.x), hn::DemoteTo(df, lanes.n.y), hn::DemoteTo(df, lanes.n.z), df, n_out);
    hn::StoreInterleaved2(hn::DemoteTo(df, lanes.u), hn::DemoteTo(df, lanes.v), df, uv_out);
    hn::Store(hn::DemoteTo(df, hn::Div(hn::Mul(texels_per_metre, lanes.t), fx)), df, m_out);
    std::copy(t_out, t_out + n, depth + k);
    std::copy(p_out, p_out + 3 * n, position[k].data());  // Vec3f and Vec2f are packed floats
    std::copy(n_out, n_out + 3 * n, normal[k].data());
    std::copy(uv_out, uv_out + 2 * n, uv[k].data());
    std::copy(m_out, m_out + n, mask_texels + k);
    hn::StoreMaskBits(d, lanes.fallback, bits);
    fallback |= (uint64_t(bits[0]) & ((uint64_t(1) << n) - 1)) << k;
  }
  return fallback;
}

}  // namespace silva::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace silva::render {

HWY_EXPORT(HitGeometryRunImpl);

uint64_t hit_geometry_run(const Camera& cam, const HitGeometry& h, const double* ray_x, double ray_y, size_t count,
                          float* depth, Vec3f* position, Vec3f* normal, Vec2f* uv, float* mask_texels) {
  return HWY_DYNAMIC_DISPATCH(HitGeometryRunImpl)(cam, h, ray_x, ray_y, count, depth, position, normal, uv, mask_texels);
}

}  // namespace silva::render
#endif  // HWY_ONCE
