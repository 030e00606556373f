// The per-target kernel is compiled once per Highway target (foreach_target) and chosen at run
// time. Only correctly rounded operations in the scalar setup's order (no MulAdd), and a rounding
// built from truncation and exact subtraction, so every target agrees with the scalar code.
#include "render/vertex_lanes.hpp"

#include <algorithm>

#include "render/raster_conventions.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/vertex_lanes.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace silva::render::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

/// round_half_away on double lanes: truncate, then step away from zero when the exact remainder
/// is at least one half.
template <class D, class V>
auto round_half_away_lanes(D d, V x) {
  const hn::RebindToSigned<D> di;
  const auto i = hn::ConvertTo(di, x);
  const auto frac = hn::Sub(x, hn::ConvertTo(d, i));
  const auto up = hn::RebindMask(di, hn::Ge(frac, hn::Set(d, 0.5)));
  const auto down = hn::RebindMask(di, hn::Le(frac, hn::Set(d, -0.5)));
  const auto one = hn::Set(di, int64_t(1));
  return hn::Sub(hn::Add(i, hn::IfThenElseZero(up, one)), hn::IfThenElseZero(down, one));
}

/// project_vertices for one target.
void ProjectVerticesImpl(const Eigen::Matrix<double, 3, 4>& m, const ViewProjection& view, const Vec3f* positions,
                         size_t count, SetupVertex* out) {
  const hn::ScalableTag<double> d;
  const hn::RebindToSigned<decltype(d)> di;
  constexpr size_t kMax = hn::MaxLanes(d);
  const size_t N = hn::Lanes(d);
  HWY_ALIGN double in[3][kMax];
  HWY_ALIGN double view_xyz[3][kMax];
  HWY_ALIGN int64_t snapped[2][kMax];
  HWY_ALIGN double depth[kMax];
  const double focal[2] = {view.fx, view.fy}, centre[2] = {view.cx, view.cy};
  for (size_t first = 0; first < count; first += N) {
    const size_t n = std::min(N, count - first);
    for (size_t k = 0; k < N; ++k) {
      const Vec3f& p = positions[first + std::min(k, n - 1)];  // the tail repeats the last vertex
      for (int c = 0; c < 3; ++c) in[c][k] = double(p[c]);
    }
    const auto x = hn::Load(d, in[0]), y = hn::Load(d, in[1]), z = hn::Load(d, in[2]);
    for (int r = 0; r < 3; ++r) {
      const auto row = hn::Add(hn::Add(hn::Add(hn::Mul(hn::Set(d, m(r, 0)), x), hn::Mul(hn::Set(d, m(r, 1)), y)),
                                       hn::Mul(hn::Set(d, m(r, 2)), z)),
                               hn::Set(d, m(r, 3)));
      hn::Store(row, d, view_xyz[r]);
    }
    const auto vz = hn::Load(d, view_xyz[2]);
    for (int a = 0; a < 2; ++a) {
      const auto screen = hn::Add(hn::Div(hn::Mul(hn::Set(d, focal[a]), hn::Load(d, view_xyz[a])), vz), hn::Set(d, centre[a]));
      hn::Store(round_half_away_lanes(d, hn::Mul(screen, hn::Set(d, double(kSubpixelScale)))), di, snapped[a]);
    }
    hn::Store(hn::Div(hn::Set(d, 1.0), vz), d, depth);
    for (size_t k = 0; k < n; ++k) {
      SetupVertex& v = out[first + k];
      v.p = Vec3d(view_xyz[0][k], view_xyz[1][k], view_xyz[2][k]);
      v.x = snapped[0][k];
      v.y = snapped[1][k];
      v.depth = depth[k];
      v.projected = true;
    }
  }
}

/// The target this copy of the kernel was compiled for.
int64_t VertexTargetImpl() { return HWY_TARGET; }

}  // namespace silva::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace silva::render {

HWY_EXPORT(ProjectVerticesImpl);
HWY_EXPORT(VertexTargetImpl);

void project_vertices(const Eigen::Matrix<double, 3, 4>& m, const ViewProjection& view, const Vec3f* positions,
                      size_t count, SetupVertex* out) {
  HWY_DYNAMIC_DISPATCH(ProjectVerticesImpl)(m, view, positions, count, out);
}

int64_t vertex_simd_target() { return HWY_DYNAMIC_DISPATCH(VertexTargetImpl)(); }

}  // namespace silva::render
#endif  // HWY_ONCE
