// The per-target kernel is compiled once per Highway target (foreach_target) and chosen at run
// time. Each lane repeats the scalar resolve's operations in its order with correctly rounded
// operations only (no MulAdd), including the association Eigen gives them in the scalar build:
// 3-term dot products and the first two rows of a 3x3 matrix-vector product sum left to right,
// the third row sums its last two terms first.
#include "render/resolve_lanes.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/resolve_lanes.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace silva::render::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

using DTag = hn::ScalableTag<double>;
using V = hn::Vec<DTag>;

/// Three lanes of a vector quantity.
struct V3 {
  V x, y, z;
};

/// a . b summed left to right.
V dot(const V3& a, const V3& b) {
  return hn::Add(hn::Add(hn::Mul(a.x, b.x), hn::Mul(a.y, b.y)), hn::Mul(a.z, b.z));
}

/// a x b.
V3 cross(const V3& a, const V3& b) {
  return {hn::Sub(hn::Mul(a.y, b.z), hn::Mul(a.z, b.y)), hn::Sub(hn::Mul(a.z, b.x), hn::Mul(a.x, b.z)),
          hn::Sub(hn::Mul(a.x, b.y), hn::Mul(a.y, b.x))};
}

/// Row r of m (three lane values) times v: rows 0 and 1 summed left to right, row 2 last two first.
V matrix_row(const V m[3], const V3& v, int r) {
  const V a = hn::Mul(m[0], v.x), b = hn::Mul(m[1], v.y), c = hn::Mul(m[2], v.z);
  return r < 2 ? hn::Add(hn::Add(a, b), c) : hn::Add(a, hn::Add(b, c));
}

/// b0 * a + b1 * b + b2 * c, summed left to right.
V blend(V b0, V b1, V b2, V a, V b, V c) { return hn::Add(hn::Add(hn::Mul(b0, a), hn::Mul(b1, b)), hn::Mul(b2, c)); }

/// Each component of v divided by s.
V3 divided(const V3& v, V s) { return {hn::Div(v.x, s), hn::Div(v.y, s), hn::Div(v.z, s)}; }

/// v where `m`, else w.
template <class M>
V3 select(M m, const V3& v, const V3& w) {
  return {hn::IfThenElse(m, v.x, w.x), hn::IfThenElse(m, v.y, w.y), hn::IfThenElse(m, v.z, w.z)};
}

/// -v.
V3 negated(const V3& v) { return {hn::Neg(v.x), hn::Neg(v.y), hn::Neg(v.z)}; }

void ResolveHitsImpl(const ResolveRow& row, const ResolvedHits& out) {
  const DTag d;
  const hn::RebindToSigned<DTag> di;
  const size_t N = hn::Lanes(d);
  constexpr int64_t kStride = int64_t(sizeof(ResolveTriangle) / sizeof(double));
  static_assert(sizeof(ResolveTriangle) % sizeof(double) == 0, "ResolveTriangle is whole doubles");
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0), third = hn::Set(d, 1.0 / 3.0);
  const V3 origin{hn::Set(d, row.origin[0]), hn::Set(d, row.origin[1]), hn::Set(d, row.origin[2])};
  V rot[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) rot[r][c] = hn::Set(d, row.rotation[r][c]);
  const V ray_y = hn::Set(d, row.ray_y);
  for (size_t i = 0; i < row.count; i += N) {
    const auto at = hn::Mul(hn::LoadU(di, row.triangle + i), hn::Set(di, kStride));
    // A field of triangle 0 addresses that field of every triangle (records kStride doubles apart).
    const ResolveTriangle& t0 = row.triangles[0];
    const auto field = [&](const double& f) { return hn::GatherIndex(d, &f, at); };
    const auto field3 = [&](const double (&f)[3]) { return V3{field(f[0]), field(f[1]), field(f[2])}; };
    // The ray: R * (x, y, 1) with camera z = 1, so t is metric z.
    const V3 ray{hn::LoadU(d, row.ray_x + i), ray_y, one};
    const V3 dir{matrix_row(rot[0], ray, 0), matrix_row(rot[1], ray, 1), matrix_row(rot[2], ray, 2)};
    const V3 e1 = field3(t0.e1), e2 = field3(t0.e2);
    const V3 pvec = cross(dir, e2);
    const V det = dot(e1, pvec);
    const auto solid = hn::Ne(det, zero);
    V b1 = hn::IfThenElse(solid, hn::Div(dot(field3(t0.s), pvec), det), third);
    V b2 = hn::IfThenElse(solid, hn::Div(dot(dir, field3(t0.qvec)), det), third);
    V t = hn::IfThenElse(solid, hn::Div(field(t0.e2_dot_q), det), zero);
    const auto ahead = hn::Gt(t, zero);  // else parallel to the plane: the centroid's depth
    t = hn::IfThenElse(ahead, t, field(t0.fallback_t));
    b1 = hn::IfThenElse(ahead, b1, third);
    b2 = hn::IfThenElse(ahead, b2, third);
    const V b0 = hn::Sub(hn::Sub(one, b1), b2);
    // Interpolated vertex normal through the cofactor matrix, or the geometric normal.
    V3 n_obj;
    V* n_obj_axis[3] = {&n_obj.x, &n_obj.y, &n_obj.z};
    for (int a = 0; a < 3; ++a)
      *n_obj_axis[a] = blend(b0, b1, b2, field(t0.normal[0][a]), field(t0.normal[1][a]), field(t0.normal[2][a]));
    V3 n;
    V* n_axis[3] = {&n.x, &n.y, &n.z};
    for (int r = 0; r < 3; ++r) {
      const V cof_row[3] = {field(t0.cof[r][0]), field(t0.cof[r][1]), field(t0.cof[r][2])};
      *n_axis[r] = matrix_row(cof_row, n_obj, r);
    }
    n = select(hn::Ne(field(t0.has_normals), zero), n, field3(t0.geometric));
    const V len = hn::Sqrt(dot(n, n));
    const V dir_squared = dot(dir, dir);
    const V3 away = negated(select(hn::Gt(dir_squared, zero), divided(dir, hn::Sqrt(dir_squared)), dir));
    n = select(hn::Gt(len, zero), divided(n, len), away);
    n = select(hn::Gt(dot(n, dir), zero), negated(n), n);
    const auto has_uvs = hn::Ne(field(t0.has_uvs), zero);
    for (int a = 0; a < 2; ++a)
      hn::StoreU(hn::IfThenElseZero(has_uvs, blend(b0, b1, b2, field(t0.uv[0][a]), field(t0.uv[1][a]), field(t0.uv[2][a]))),
                 d, out.uv[a] + i);
    hn::StoreU(t, d, out.t + i);
    hn::StoreU(hn::Add(origin.x, hn::Mul(t, dir.x)), d, out.position[0] + i);
    hn::StoreU(hn::Add(origin.y, hn::Mul(t, dir.y)), d, out.position[1] + i);
    hn::StoreU(hn::Add(origin.z, hn::Mul(t, dir.z)), d, out.position[2] + i);
    hn::StoreU(n.x, d, out.normal[0] + i);
    hn::StoreU(n.y, d, out.normal[1] + i);
    hn::StoreU(n.z, d, out.normal[2] + i);
  }
}

/// Lanes of this target.
size_t LanesImpl() { return hn::Lanes(DTag()); }

}  // namespace silva::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace silva::render {

HWY_EXPORT(ResolveHitsImpl);
HWY_EXPORT(LanesImpl);

size_t resolve_lane_padding() { return HWY_DYNAMIC_DISPATCH(LanesImpl)(); }

void resolve_hits_lanes(const ResolveRow& row, const ResolvedHits& out) {
  HWY_DYNAMIC_DISPATCH(ResolveHitsImpl)(row, out);
}

}  // namespace silva::render
#endif  // HWY_ONCE
