// The per-target kernel is compiled once per Highway target (foreach_target) and chosen at run
// time. core/noise.cpp's simplex2 and fbm2 step for step: correctly rounded adds and multiplies in
// the scalar order, exact floors and integer conversions of whole numbers, the permutation and the
// gradients read through tables of 512 entries (index i holds what the scalar code finds at i & 255).
#include "world/noise_lanes.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "world/noise_lanes.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

#ifndef SILVA_WORLD_NOISE_LANES_TABLES
#define SILVA_WORLD_NOISE_LANES_TABLES
namespace silva::world::noise_tables {

/// Permutation, gradient x and gradient y at every index 0..511 (the scalar code's perm(i) and
/// kGrad[perm(i) % 12]), as lane-wide integers and doubles.
struct Tables {
  std::array<int64_t, 512> perm;  ///< perm(i) = permutation[i & 255]
  std::array<double, 512> grad_x; ///< x of the gradient perm(i) % 12 picks
  std::array<double, 512> grad_y; ///< y of the gradient perm(i) % 12 picks
};

/// The tables, built once from simplex2_tables() (core/noise.hpp).
inline const Tables& tables() {
  static const Tables t = [] {
    Tables out{};
    const SimplexTables s = simplex2_tables();
    for (int i = 0; i < 512; ++i) {
      const int p = s.permutation[i & 255];
      out.perm[size_t(i)] = p;
      out.grad_x[size_t(i)] = s.gradients[p % 12][0];
      out.grad_y[size_t(i)] = s.gradients[p % 12][1];
    }
    return out;
  }();
  return t;
}

}  // namespace silva::world::noise_tables
#endif

HWY_BEFORE_NAMESPACE();
namespace silva::world::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

/// One simplex corner's contribution at offset (x, y) with gradient (gx, gy): core/noise.cpp's corner.
template <class D, class V>
V Corner(D d, V x, V y, V gx, V gy) {
  const V t = hn::Sub(hn::Sub(hn::Set(d, 0.5), hn::Mul(x, x)), hn::Mul(y, y));
  const V t2 = hn::Mul(t, t);
  const V value = hn::Mul(hn::Mul(t2, t2), hn::Add(hn::Mul(gx, x), hn::Mul(gy, y)));
  return hn::IfThenZeroElse(hn::Lt(t, hn::Zero(d)), value);
}

/// simplex2 of every lane.
template <class D, class V>
V Simplex2(D d, V xin, V yin, const noise_tables::Tables& tab) {
  const hn::RebindToSigned<D> di;
  const double F2 = 0.5 * (std::sqrt(3.0) - 1.0);
  const double G2 = (3.0 - std::sqrt(3.0)) / 6.0;
  const V s = hn::Mul(hn::Add(xin, yin), hn::Set(d, F2));
  const V fi = hn::Floor(hn::Add(xin, s));
  const V fj = hn::Floor(hn::Add(yin, s));
  const V t = hn::Mul(hn::Add(fi, fj), hn::Set(d, G2));
  const V x0 = hn::Sub(xin, hn::Sub(fi, t));
  const V y0 = hn::Sub(yin, hn::Sub(fj, t));
  const auto x_first = hn::Gt(x0, y0);  // i1 = 1, j1 = 0
  const V one = hn::Set(d, 1.0);
  const V x1 = hn::Add(hn::Sub(x0, hn::IfThenElseZero(x_first, one)), hn::Set(d, G2));
  const V y1 = hn::Add(hn::Sub(y0, hn::IfThenZeroElse(x_first, one)), hn::Set(d, G2));
  const V x2 = hn::Add(hn::Sub(x0, one), hn::Set(d, 2.0 * G2));
  const V y2 = hn::Add(hn::Sub(y0, one), hn::Set(d, 2.0 * G2));
  const auto mask255 = hn::Set(di, 255);
  const auto ii = hn::And(hn::ConvertTo(di, fi), mask255);
  const auto jj = hn::And(hn::ConvertTo(di, fj), mask255);
  const auto i1 = hn::IfThenElseZero(hn::RebindMask(di, x_first), hn::Set(di, 1));
  const auto j1 = hn::Sub(hn::Set(di, 1), i1);
  const auto k1 = hn::Set(di, 1);
  const int64_t* perm = tab.perm.data();
  const auto c0 = hn::Add(ii, hn::GatherIndex(di, perm, jj));
  const auto c1 = hn::Add(hn::Add(ii, i1), hn::GatherIndex(di, perm, hn::Add(jj, j1)));
  const auto c2 = hn::Add(hn::Add(ii, k1), hn::GatherIndex(di, perm, hn::Add(jj, k1)));
  const double* gx = tab.grad_x.data();
  const double* gy = tab.grad_y.data();
  const V n0 = Corner(d, x0, y0, hn::GatherIndex(d, gx, c0), hn::GatherIndex(d, gy, c0));
  const V n1 = Corner(d, x1, y1, hn::GatherIndex(d, gx, c1), hn::GatherIndex(d, gy, c1));
  const V n2 = Corner(d, x2, y2, hn::GatherIndex(d, gx, c2), hn::GatherIndex(d, gy, c2));
  return hn::Mul(hn::Set(d, 70.0), hn::Add(hn::Add(n0, n1), n2));
}

/// fbm2 of the lanes of (xs, ys).
template <class D, class V>
V Fbm2(D d, const FbmParams& p, V xs, V ys, const noise_tables::Tables& tab) {
  V sum = hn::Zero(d);
  double amp_sum = 0.0, amp = 1.0, freq = p.frequency;
  for (int o = 0; o < p.octaves; ++o) {
    const double shift = 31.7 * o;
    const V u = hn::Add(hn::Mul(xs, hn::Set(d, freq)), hn::Set(d, p.offset_x + shift));
    const V v = hn::Add(hn::Mul(ys, hn::Set(d, freq)), hn::Set(d, p.offset_y + shift));
    sum = hn::Add(sum, hn::Mul(hn::Set(d, amp), Simplex2(d, u, v, tab)));
    amp_sum += amp;
    amp *= p.persistence;
    freq *= p.lacunarity;
  }
  return amp_sum > 0.0 ? hn::Div(sum, hn::Set(d, amp_sum)) : hn::Zero(d);
}

/// fbm2_lanes for one target.
void Fbm2LanesImpl(const FbmParams& p, const double* x, const double* y, double* out, size_t n) {
  const hn::ScalableTag<double> d;
  const size_t N = hn::Lanes(d);
  const noise_tables::Tables& tab = noise_tables::tables();
  size_t k = 0;
  for (; k + N <= n; k += N) hn::StoreU(Fbm2(d, p, hn::LoadU(d, x + k), hn::LoadU(d, y + k), tab), d, out + k);
  if (k == n) return;
  // The last partial vector through padded copies (the padding lanes' values are dropped).
  HWY_ALIGN double tail_x[hn::MaxLanes(d)] = {}, tail_y[hn::MaxLanes(d)] = {}, tail_out[hn::MaxLanes(d)];
  std::copy(x + k, x + n, tail_x);
  std::copy(y + k, y + n, tail_y);
  hn::Store(Fbm2(d, p, hn::Load(d, tail_x), hn::Load(d, tail_y), tab), d, tail_out);
  std::copy(tail_out, tail_out + (n - k), out + k);
}

/// The target this copy of the kernel was compiled for.
int64_t Fbm2LanesTargetImpl() { return HWY_TARGET; }

}  // namespace silva::world::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace silva::world {

HWY_EXPORT(Fbm2LanesImpl);
HWY_EXPORT(Fbm2LanesTargetImpl);

void fbm2_lanes(const FbmParams& params, const double* x, const double* y, double* out, size_t n) {
  HWY_DYNAMIC_DISPATCH(Fbm2LanesImpl)(params, x, y, out, n);
}

int64_t fbm2_lanes_simd_target() { return HWY_DYNAMIC_DISPATCH(Fbm2LanesTargetImpl)(); }

}  // namespace silva::world
#endif  // HWY_ONCE
