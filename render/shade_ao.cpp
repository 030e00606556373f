// The per-target kernel is compiled once per Highway target (foreach_target) and chosen at run
// time. Only correctly rounded operations in a fixed order (no MulAdd), so every target agrees.
#include "render/shade_ao.hpp"

#include <algorithm>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/shade_ao.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace silva::render::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

/// Sample offsets on the unit disc: 8 directions, alternating full and half radius.
constexpr float kPattern[8][2] = {{1.0f, 0.0f},       {0.354f, 0.354f},  {0.0f, 1.0f},   {-0.354f, 0.354f},
                                  {-1.0f, 0.0f},      {-0.354f, -0.354f}, {0.0f, -1.0f}, {0.354f, -0.354f}};

/// screen_space_ao of `count` pixels of row v into out, one pixel per float lane: pixel k is at
/// column columns[k], or u0 + k step when `columns` is null.
void AoRowImpl(const GBuffer& g, const Camera& camera, int v, const int32_t* columns, int u0, int step, int count,
               float* out) {
  const hn::ScalableTag<float> d;
  const hn::RebindToSigned<decltype(d)> di;
  const int N = int(hn::Lanes(d));
  const float* position = g.position.data()->data();  // Vec3f is three packed floats
  const float* normal = g.normal.data()->data();
  const float* depth = g.depth.data();
  const auto zero = hn::Zero(d);
  const auto width_i = hn::Set(di, g.width);
  const auto dot = [](auto ax, auto ay, auto az, auto bx, auto by, auto bz) {
    return hn::Add(hn::Mul(ax, bx), hn::Add(hn::Mul(ay, by), hn::Mul(az, bz)));
  };
  for (int first = 0; first < count; first += N) {
    const int n = std::min(N, count - first);
    const auto live = hn::FirstN(di, size_t(n));
    auto u = hn::Add(hn::Set(di, u0 + first * step), hn::Mul(hn::Iota(di, 0), hn::Set(di, step)));
    if (columns) {
      HWY_ALIGN int32_t listed[hn::MaxLanes(di)] = {};
      std::copy(columns + first, columns + first + n, listed);
      u = hn::Load(di, listed);
    }
    const auto i = hn::IfThenElseZero(live, hn::Add(hn::Mul(hn::Set(di, v), width_i), u));  // dead lanes read pixel 0
    const auto i3 = hn::Mul(i, hn::Set(di, 3));
    const auto gather3 = [&](const float* base, auto index3, int c) {
      return hn::GatherIndex(d, base, hn::Add(index3, hn::Set(di, c)));
    };
    const auto px = gather3(position, i3, 0), py = gather3(position, i3, 1), pz = gather3(position, i3, 2);
    const auto nx = gather3(normal, i3, 0), ny = gather3(normal, i3, 1), nz = gather3(normal, i3, 2);
    const auto z = hn::GatherIndex(d, depth, i);
    // Screen offsets reach 0.6 kAoRadius at the pixel's depth, so most samples land within the radius.
    const auto radius_px = hn::Min(
        hn::Max(hn::Div(hn::Set(d, float(camera.fx) * (0.6f * kAoRadius)), z), hn::Set(d, 1.5f)), hn::Set(d, 48.0f));
    auto occlusion = zero;
    for (const auto& o : kPattern) {
      const auto offset = [&](float k) { return hn::ConvertTo(di, hn::Mul(hn::Set(d, k), radius_px)); };
      const auto su = hn::Min(hn::Max(hn::Add(u, offset(o[0])), hn::Zero(di)), hn::Set(di, g.width - 1));
      const auto sv = hn::Min(hn::Max(hn::Add(hn::Set(di, v), offset(o[1])), hn::Zero(di)), hn::Set(di, g.height - 1));
      const auto s = hn::Add(hn::Mul(sv, width_i), su);
      const auto s3 = hn::Mul(s, hn::Set(di, 3));
      const auto dx = hn::Sub(gather3(position, s3, 0), px);
      const auto dy = hn::Sub(gather3(position, s3, 1), py);
      const auto dz = hn::Sub(gather3(position, s3, 2), pz);
      const auto d2 = dot(dx, dy, dz, dx, dy, dz);
      const auto use = hn::And(hn::And(hn::RebindMask(d, hn::Ne(s, i)), hn::Ne(hn::GatherIndex(d, depth, s), zero)),
                               hn::And(hn::Gt(d2, hn::Set(d, 1e-8f)), hn::Lt(d2, hn::Set(d, kAoRadius * kAoRadius))));
      const auto elevation = hn::Div(dot(nx, ny, nz, dx, dy, dz), hn::Sqrt(d2));
      const auto weight = hn::Sub(hn::Set(d, 1.0f), hn::Mul(d2, hn::Set(d, 1.0f / (kAoRadius * kAoRadius))));
      occlusion = hn::Add(occlusion, hn::IfThenElseZero(use, hn::Mul(hn::Max(hn::Sub(elevation, hn::Set(d, 0.1f)), zero), weight)));
    }
    const auto ao = hn::Max(zero, hn::Sub(hn::Set(d, 1.0f), hn::Mul(occlusion, hn::Set(d, 1.5f / 8.0f))));
    HWY_ALIGN float tmp[hn::MaxLanes(d)];
    hn::Store(ao, d, tmp);
    std::copy(tmp, tmp + n, out + first);
  }
}

/// The target this copy of the kernel was compiled for.
int64_t AoTargetImpl() { return HWY_TARGET; }

}  // namespace silva::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace silva::render {

HWY_EXPORT(AoRowImpl);
HWY_EXPORT(AoTargetImpl);

void screen_space_ao_row(const GBuffer& g, const Camera& camera, int v, int u0, int step, int count, float* out) {
  if (count > 0) HWY_DYNAMIC_DISPATCH(AoRowImpl)(g, camera, v, nullptr, u0, step, count, out);
}

void screen_space_ao_columns(const GBuffer& g, const Camera& camera, int v, const int32_t* columns, int count,
                             float* out) {
  if (count > 0) HWY_DYNAMIC_DISPATCH(AoRowImpl)(g, camera, v, columns, 0, 0, count, out);
}

float screen_space_ao(const GBuffer& g, const Camera& camera, int u, int v) {
  float ao = 1.0f;
  screen_space_ao_row(g, camera, v, u, 1, 1, &ao);
  return ao;
}

int64_t ao_simd_target() { return HWY_DYNAMIC_DISPATCH(AoTargetImpl)(); }

}  // namespace silva::render
#endif  // HWY_ONCE
