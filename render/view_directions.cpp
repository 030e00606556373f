// The per-target kernel is compiled once per Highway target (foreach_target) and chosen at run
// time. Correctly rounded double adds, multiplies, divides and square roots in Camera's order,
// rounded to float at the end, so every target returns the scalar expression's bits.
#include "render/view_directions.hpp"

#include <algorithm>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/view_directions.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace silva::render::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

/// view_directions_row for one target.
void ViewDirectionsRowImpl(const Camera& camera, int v, Vec3f* out) {
  const hn::ScalableTag<double> d;
  const hn::Rebind<float, decltype(d)> df;
  const size_t N = hn::Lanes(d);
  const Mat3d r = camera.camera_to_world.block<3, 3>(0, 0);
  const double y = camera.ray_y(v);
  // Row k of R (x, y, 1): rows 0 and 1 sum left to right, row 2 as a0 + (a1 + a2), as Eigen's
  // fixed-size product does; the y and 1 terms of each row are the same on every lane.
  const auto row01 = [&](int k, auto x) {
    return hn::Add(hn::Add(hn::Mul(hn::Set(d, r(k, 0)), x), hn::Set(d, r(k, 1) * y)), hn::Set(d, r(k, 2)));
  };
  const auto y2 = hn::Set(d, r(2, 1) * y + r(2, 2));
  float* xyz = out->data();  // Vec3f is three packed floats
  const size_t width = size_t(camera.width);
  for (size_t u = 0; u < width; u += N) {
    const auto column = hn::Add(hn::Set(d, double(u)), hn::Iota(d, 0.0));
    const auto x = hn::Div(hn::Sub(hn::Add(column, hn::Set(d, 0.5)), hn::Set(d, camera.cx)), hn::Set(d, camera.fx));
    auto wx = row01(0, x), wy = row01(1, x);
    auto wz = hn::Add(hn::Mul(hn::Set(d, r(2, 0)), x), y2);
    const auto squared = hn::Add(hn::Add(hn::Mul(wx, wx), hn::Mul(wy, wy)), hn::Mul(wz, wz));
    const auto positive = hn::Gt(squared, hn::Zero(d));
    const auto length = hn::Sqrt(squared);
    wx = hn::IfThenElse(positive, hn::Div(wx, length), wx);
    wy = hn::IfThenElse(positive, hn::Div(wy, length), wy);
    wz = hn::IfThenElse(positive, hn::Div(wz, length), wz);
    const size_t n = std::min(N, width - u);
    if (n == N) {
      hn::StoreInterleaved3(hn::DemoteTo(df, wx), hn::DemoteTo(df, wy), hn::DemoteTo(df, wz), df, xyz + 3 * u);
    } else {
      HWY_ALIGN float tail[3 * hn::MaxLanes(d)];
      hn::StoreInterleaved3(hn::DemoteTo(df, wx), hn::DemoteTo(df, wy), hn::DemoteTo(df, wz), df, tail);
      std::copy(tail, tail + 3 * n, xyz + 3 * u);
    }
  }
}

/// The target this copy of the kernel was compiled for.
int64_t ViewDirectionsTargetImpl() { return HWY_TARGET; }

}  // namespace silva::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace silva::render {

HWY_EXPORT(ViewDirectionsRowImpl);
HWY_EXPORT(ViewDirectionsTargetImpl);

void view_directions_row(const Camera& camera, int v, Vec3f* out) {
  HWY_DYNAMIC_DISPATCH(ViewDirectionsRowImpl)(camera, v, out);
}

int64_t view_directions_simd_target() { return HWY_DYNAMIC_DISPATCH(ViewDirectionsTargetImpl)(); }

}  // namespace silva::render
#endif  // HWY_ONCE
