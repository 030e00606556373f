// The per-target kernel is compiled once per Highway target (foreach_target) and chosen at run
// time. Only correctly rounded operations in a fixed order (no MulAdd), so every target agrees.
#include "render/fog_amounts.hpp"

#include <algorithm>

#include "core/det_math.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/fog_amounts.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace silva::render::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

/// det_expf on float lanes: the same clamp, range reduction, degree-7 polynomial and 2^k scaling.
template <class D, class V>
V exp_lanes(D d, V x) {
  const hn::RebindToSigned<D> di;
  constexpr float kLn2Hi = 0.693145751953125f, kLn2Lo = 1.428606765330187e-06f;
  constexpr float kInvLn2 = 1.44269504088896341f;
  constexpr float kRound = 12582912.0f;
  const auto underflow = hn::Lt(x, hn::Set(d, -87.0f));
  x = hn::Min(hn::Max(x, hn::Set(d, -87.0f)), hn::Set(d, 88.0f));  // the max only keeps dead lanes finite
  const V k = hn::Sub(hn::Add(hn::Mul(x, hn::Set(d, kInvLn2)), hn::Set(d, kRound)), hn::Set(d, kRound));
  const V r = hn::Sub(hn::Sub(x, hn::Mul(k, hn::Set(d, kLn2Hi))), hn::Mul(k, hn::Set(d, kLn2Lo)));
  V p = hn::Set(d, float(kInverseFactorials.v[7]));
  for (int n = 6; n >= 0; --n) p = hn::Add(hn::Mul(p, r), hn::Set(d, float(kInverseFactorials.v[n])));
  const auto bits = hn::ShiftLeft<23>(hn::Add(hn::ConvertTo(di, k), hn::Set(di, 127)));
  return hn::IfThenZeroElse(underflow, hn::Mul(p, hn::BitCast(d, bits)));
}

/// fog_amounts for one target.
void FogAmountsImpl(const FogAmountParams& fog, const Vec3f* points, size_t count, float* out) {
  if (count == 0) return;
  if (fog.camera_density <= 0.0f) {
    std::fill(out, out + count, 0.0f);
    return;
  }
  const hn::ScalableTag<float> d;
  const size_t N = hn::Lanes(d);
  const float* xyz = points->data();  // Vec3f is three packed floats
  const auto one = hn::Set(d, 1.0f);
  size_t i = 0;
  for (; i < count; i += N) {
    const size_t n = std::min(N, count - i);
    hn::Vec<decltype(d)> px, py, pz;
    if (n == N) {
      hn::LoadInterleaved3(d, xyz + 3 * i, px, py, pz);
    } else {
      HWY_ALIGN float tail[3 * hn::MaxLanes(d)] = {};
      std::copy(xyz + 3 * i, xyz + 3 * (i + n), tail);
      hn::LoadInterleaved3(d, tail, px, py, pz);
    }
    const auto dx = hn::Sub(px, hn::Set(d, fog.camera.x()));
    const auto dy = hn::Sub(py, hn::Set(d, fog.camera.y()));
    const auto dz = hn::Sub(pz, hn::Set(d, fog.camera.z()));
    const auto length = hn::Sqrt(hn::Add(hn::Mul(dx, dx), hn::Add(hn::Mul(dy, dy), hn::Mul(dz, dz))));
    const auto k = hn::Mul(hn::Set(d, fog.falloff), dz);
    const auto series = hn::Sub(one, hn::Mul(k, hn::Sub(hn::Set(d, 0.5f), hn::Mul(k, hn::Set(d, 1.0f / 6.0f)))));
    const auto closed = hn::Div(hn::Sub(one, exp_lanes(d, hn::Neg(k))), k);
    const auto height_factor = hn::IfThenElse(hn::Lt(hn::Abs(k), hn::Set(d, 1e-2f)), series, closed);
    const auto optical_depth = hn::Mul(hn::Mul(hn::Set(d, fog.camera_density), length), height_factor);
    const auto amount = hn::Sub(one, exp_lanes(d, hn::Neg(optical_depth)));
    if (n == N) {
      hn::StoreU(amount, d, out + i);
    } else {
      HWY_ALIGN float tail[hn::MaxLanes(d)];
      hn::Store(amount, d, tail);
      std::copy(tail, tail + n, out + i);
    }
  }
}

/// The target this copy of the kernel was compiled for.
int64_t FogTargetImpl() { return HWY_TARGET; }

}  // namespace silva::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace silva::render {

HWY_EXPORT(FogAmountsImpl);
HWY_EXPORT(FogTargetImpl);

void fog_amounts(const FogAmountParams& fog, const Vec3f* points, size_t count, float* out) {
  HWY_DYNAMIC_DISPATCH(FogAmountsImpl)(fog, points, count, out);
}

int64_t fog_simd_target() { return HWY_DYNAMIC_DISPATCH(FogTargetImpl)(); }

}  // namespace silva::render
#endif  // HWY_ONCE
