// The per-target kernel is compiled once per Highway target (foreach_target) and chosen at run
// time. Only correctly rounded operations in a fixed order (no MulAdd), so every target agrees.
#include "render/shadow_lookup.hpp"

#include <algorithm>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/shadow_lookup.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace silva::render::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

constexpr double kMaxSlope = 8.0;        ///< Largest receiver depth gradient used (metres per metre).
constexpr double kConstantBias = 0.02;  ///< Metres, on top of half a texel.
/// Radius (texels) of the round PCF filter: sunflecks and penumbrae come out round (on the ground, ellipses
/// stretched along the sun's azimuth, as the sun's images through canopy gaps are), not texel squares.
constexpr float kFilterRadius = 2.0f;

/// Double lanes: one receiver point per lane.
using DTag = hn::ScalableTag<double>;

/// Per-lane inputs widened to double (lane k = point first + k).
struct Lanes {
  HWY_ALIGN double v[6][hn::MaxLanes(DTag())];  ///< position x, y, z, normal x, y, z.
};

/// Visibility of up to Lanes(d) points; see shadow_visibility_row for the operation order.
void visibility_lanes(const ShadowMap& map, const Lanes& in, const Vec3f& to_sun, float* out, size_t n) {
  const DTag d;
  const hn::Rebind<float, DTag> df;
  const hn::Rebind<int32_t, DTag> di;
  const auto load = [&](int k) { return hn::Load(d, in.v[k]); };
  const auto set = [&](double x) { return hn::Set(d, x); };
  const Eigen::Matrix<double, 4, 4, Eigen::RowMajor> m = map.world_to_light;
  const double texel = map.texel_size;
  // Normal turned towards the sun, point pushed one texel along it.
  const auto nx0 = load(3), ny0 = load(4), nz0 = load(5);
  const auto facing = hn::Add(hn::Mul(nx0, set(to_sun.x())), hn::Add(hn::Mul(ny0, set(to_sun.y())), hn::Mul(nz0, set(to_sun.z()))));
  const auto side = hn::IfThenElse(hn::Lt(facing, set(0.0)), set(-1.0), set(1.0));
  const auto nx = hn::Mul(nx0, side), ny = hn::Mul(ny0, side), nz = hn::Mul(nz0, side);
  const auto px = hn::Add(load(0), hn::Mul(nx, set(texel)));
  const auto py = hn::Add(load(1), hn::Mul(ny, set(texel)));
  const auto pz = hn::Add(load(2), hn::Mul(nz, set(texel)));
  const auto row = [&](int r, auto x, auto y, auto z, double w) {
    const auto s = hn::Add(hn::Add(hn::Mul(set(m(r, 0)), x), hn::Mul(set(m(r, 1)), y)), hn::Mul(set(m(r, 2)), z));
    return w == 0.0 ? s : hn::Add(s, set(w));
  };
  const auto lx = row(0, px, py, pz, m(0, 3)), ly = row(1, px, py, pz, m(1, 3)), lz = row(2, px, py, pz, m(2, 3));
  const auto fx = hn::Div(hn::Sub(lx, set(map.origin_x)), set(texel));
  const auto fy = hn::Div(hn::Sub(ly, set(map.origin_y)), set(texel));
  const auto inside = hn::And(hn::And(hn::Ge(fx, set(0.0)), hn::Ge(fy, set(0.0))),
                              hn::And(hn::Lt(fx, set(double(map.width))), hn::Lt(fy, set(double(map.height)))));
  // Receiver plane in light space: depth changes by (gx, gy) per metre of light x, y.
  const auto nlx = row(0, nx, ny, nz, 0.0), nly = row(1, nx, ny, nz, 0.0), nlz = row(2, nx, ny, nz, 0.0);
  const auto nlz_safe = hn::IfThenElse(hn::Lt(nlz, set(0.0)), hn::Min(nlz, set(-1e-6)), hn::Max(nlz, set(1e-6)));
  const auto slope = [&](auto v) { return hn::Min(hn::Max(hn::Div(hn::Neg(v), nlz_safe), set(-kMaxSlope)), set(kMaxSlope)); };
  const auto gx = slope(nlx), gy = slope(nly);
  const auto base = hn::Sub(lz, set(0.5 * texel + kConstantBias));
  // Round filter: the 4x4 texels around the point, texel (i, j) at (i - 1 - ax, j - 1 - ay) texels from it,
  // each weighing max(0, 1 - d^2 / kFilterRadius^2); the texels beyond the 4x4 lie farther than the radius.
  const auto sx = hn::Sub(fx, set(0.5)), sy = hn::Sub(fy, set(0.5));
  const auto fx0 = hn::Floor(sx), fy0 = hn::Floor(sy);
  const auto ax = hn::DemoteTo(df, hn::Sub(sx, fx0)), ay = hn::DemoteTo(df, hn::Sub(sy, fy0));
  const auto squared_offset = [&](int k, auto a) { const auto o = hn::Sub(hn::Set(df, float(k - 1)), a); return hn::Mul(o, o); };
  const decltype(ax) dx2[4] = {squared_offset(0, ax), squared_offset(1, ax), squared_offset(2, ax), squared_offset(3, ax)};
  const auto per_r2 = hn::Set(df, 1.0f / (kFilterRadius * kFilterRadius)), one_f = hn::Set(df, 1.0f);
  // Clamped first texel: the clamp also keeps lanes outside the map (or with NaN) in range.
  const auto first = [&](auto f0, int size) {
    const auto t = hn::DemoteTo(di, hn::Min(hn::Max(f0, set(-4.0)), set(double(size) + 4.0)));
    return hn::Sub(t, hn::Set(di, 1));
  };
  const auto tx = first(fx0, map.width), ty = first(fy0, map.height);
  const auto clamp_index = [&](auto t, int size) { return hn::Min(hn::Max(t, hn::Zero(di)), hn::Set(di, size - 1)); };
  hn::Vec<decltype(di)> column[4];
  hn::Vec<decltype(d)> column_offset[4];
  for (int i = 0; i < 4; ++i) {
    column[i] = clamp_index(hn::Add(tx, hn::Set(di, i)), map.width);
    const auto ox = hn::Mul(hn::Sub(hn::Add(hn::PromoteTo(d, column[i]), set(0.5)), fx), set(texel));
    column_offset[i] = hn::Add(base, hn::Mul(gx, ox));
  }
  auto lit = hn::Zero(df), dark = hn::Zero(df);
  for (int j = 0; j < 4; ++j) {
    const auto y = clamp_index(hn::Add(ty, hn::Set(di, j)), map.height);
    const auto row_offset = hn::Mul(gy, hn::Mul(hn::Sub(hn::Add(hn::PromoteTo(d, y), set(0.5)), fy), set(texel)));
    const auto row_start = hn::Mul(y, hn::Set(di, map.width));
    const auto dy2 = squared_offset(j, ay);
    for (int i = 0; i < 4; ++i) {
      const auto receiver = hn::DemoteTo(df, hn::Add(column_offset[i], row_offset));
      const auto depth = hn::GatherIndex(df, map.depth.data(), hn::Add(row_start, column[i]));
      const auto is_lit = hn::Le(receiver, depth);
      const auto w = hn::Max(hn::Sub(one_f, hn::Mul(hn::Add(dx2[i], dy2), per_r2)), hn::Zero(df));
      lit = hn::Add(lit, hn::IfThenElseZero(is_lit, w));
      dark = hn::Add(dark, hn::IfThenZeroElse(is_lit, w));
    }
  }
  // Exactly 1 when no tap is shadowed, 0 when every weighted tap is; points outside the map are lit.
  const auto ratio = hn::PromoteTo(d, hn::Div(lit, hn::Add(lit, dark)));  // exact widening and back
  const auto visible = hn::DemoteTo(df, hn::IfThenElse(inside, ratio, set(1.0)));
  HWY_ALIGN float tmp[hn::MaxLanes(df)];
  hn::Store(visible, df, tmp);
  std::copy(tmp, tmp + n, out);
}

/// shadow_visibility_row for one target.
void ShadowRowImpl(const ShadowMap& map, const Vec3f* positions, const Vec3f* normals, size_t count,
                   const Vec3f& to_sun, float* out) {
  if (map.width <= 0 || map.height <= 0 || map.texel_size <= 0.0) {
    std::fill(out, out + count, 1.0f);
    return;
  }
  const size_t N = hn::Lanes(DTag());
  Lanes in{};
  for (size_t first = 0; first < count; first += N) {
    const size_t n = std::min(N, count - first);
    for (size_t k = 0; k < n; ++k)
      for (int c = 0; c < 3; ++c) {
        in.v[c][k] = double(positions[first + k][c]);
        in.v[3 + c][k] = double(normals[first + k][c]);
      }
    visibility_lanes(map, in, to_sun, out + first, n);
  }
}

/// The target this copy of the kernel was compiled for.
int64_t ShadowTargetImpl() { return HWY_TARGET; }

}  // namespace silva::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace silva::render {

HWY_EXPORT(ShadowRowImpl);
HWY_EXPORT(ShadowTargetImpl);

void shadow_visibility_row(const ShadowMap& map, const Vec3f* positions, const Vec3f* normals, size_t count,
                           const Vec3f& to_sun, float* out) {
  if (count > 0) HWY_DYNAMIC_DISPATCH(ShadowRowImpl)(map, positions, normals, count, to_sun, out);
}

float shadow_visibility(const ShadowMap& map, const Vec3f& position, const Vec3f& normal, const Vec3f& to_sun) {
  float v = 1.0f;
  shadow_visibility_row(map, &position, &normal, 1, to_sun, &v);
  return v;
}

int64_t shadow_simd_target() { return HWY_DYNAMIC_DISPATCH(ShadowTargetImpl)(); }

}  // namespace silva::render
#endif  // HWY_ONCE
