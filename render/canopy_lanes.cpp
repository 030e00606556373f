// canopy_share_row on Highway lanes: the per-target kernel is compiled once per Highway target
// (foreach_target) and chosen at run time. Only correctly rounded operations in the scalar formula's
// order (no MulAdd), so every target gives the same bits.
#include <algorithm>

#include "render/canopy_map.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/canopy_lanes.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace silva::render::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

/// Float lanes: one surface point per lane.
using FTag = hn::ScalableTag<float>;

/// The map's light-space rows in float, x and y in cell units (the cover is smooth over metres, so float
/// precision, millimetres here, is ample), and the offsets of cell centres.
struct CellFrame {
  Vec3f rx, ry, rz;  ///< Rows of world_to_light: x and y divided by the cell size, z (depth) as is.
  float ox, oy;      ///< Light-space x, y of cell (0, 0)'s centre, in cells.
};

/// canopy_share_row for one target.
void CanopyRowImpl(const CanopyMap& map, const Vec3f* positions, size_t count, float* out) {
  if (map.width <= 0 || map.height <= 0) {
    std::fill(out, out + count, 0.0f);
    return;
  }
  const Mat4d& m = map.world_to_light;
  const float inv_cell = float(1.0 / map.cell);
  const CellFrame f{m.block<1, 3>(0, 0).transpose().cast<float>() * inv_cell,
                    m.block<1, 3>(1, 0).transpose().cast<float>() * inv_cell, m.block<1, 3>(2, 0).transpose().cast<float>(),
                    float(map.origin_x / map.cell) + 0.5f, float(map.origin_y / map.cell) + 0.5f};
  const FTag d;
  const hn::RebindToSigned<FTag> di;
  const size_t N = hn::Lanes(d);
  const auto set = [&](float x) { return hn::Set(d, x); };
  const auto one = set(1.0f), zero = hn::Zero(d);
  const auto width = hn::Set(di, map.width), height = hn::Set(di, map.height);
  HWY_ALIGN float px[hn::MaxLanes(FTag())], py[hn::MaxLanes(FTag())], pz[hn::MaxLanes(FTag())], tmp[hn::MaxLanes(FTag())];
  for (size_t first = 0; first < count; first += N) {
    const size_t n = std::min(N, count - first);
    for (size_t k = 0; k < N; ++k) {
      const Vec3f& p = positions[first + std::min(k, n - 1)];
      px[k] = p.x(), py[k] = p.y(), pz[k] = p.z();
    }
    const auto x = hn::Load(d, px), y = hn::Load(d, py), z = hn::Load(d, pz);
    const auto dot = [&](const Vec3f& r) {
      return hn::Add(hn::Add(hn::Mul(set(r.x()), x), hn::Mul(set(r.y()), y)), hn::Mul(set(r.z()), z));
    };
    const auto fx_raw = hn::Sub(dot(f.rx), set(f.ox)), fy_raw = hn::Sub(dot(f.ry), set(f.oy));
    const auto inside = hn::And(hn::And(hn::Gt(fx_raw, set(-1.0f)), hn::Gt(fy_raw, set(-1.0f))),
                                hn::And(hn::Lt(fx_raw, set(float(map.width))), hn::Lt(fy_raw, set(float(map.height)))));
    // Lanes outside the map (or NaN) read cell (0, 0) and are dropped at the end.
    const auto fx = hn::IfThenElseZero(inside, fx_raw), fy = hn::IfThenElseZero(inside, fy_raw);
    const auto x0f = hn::Floor(fx), y0f = hn::Floor(fy);
    const auto ax = hn::Sub(fx, x0f), ay = hn::Sub(fy, y0f);
    const auto x0 = hn::ConvertTo(di, x0f), y0 = hn::ConvertTo(di, y0f);
    const auto i1 = hn::Set(di, 1);
    const auto xa = hn::Max(x0, hn::Zero(di)), xb = hn::Min(hn::Add(x0, i1), hn::Sub(width, i1));
    const auto ya = hn::Max(y0, hn::Zero(di)), yb = hn::Min(hn::Add(y0, i1), hn::Sub(height, i1));
    const auto r0 = hn::Mul(ya, width), r1 = hn::Mul(yb, width);
    const hn::Vec<decltype(di)> cell[4] = {hn::Add(r0, xa), hn::Add(r0, xb), hn::Add(r1, xa), hn::Add(r1, xb)};
    const auto bx = hn::Sub(one, ax), by = hn::Sub(one, ay);
    const hn::Vec<FTag> w[4] = {hn::Mul(bx, by), hn::Mul(ax, by), hn::Mul(bx, ay), hn::Mul(ax, ay)};
    auto cover = zero, cover_depth = zero;
    for (int i = 0; i < 4; ++i) {
      const auto wc = hn::Mul(w[i], hn::GatherIndex(d, map.cover.data(), cell[i]));
      cover = hn::Add(cover, wc);
      cover_depth = hn::Add(cover_depth, hn::Mul(wc, hn::GatherIndex(d, map.depth.data(), cell[i])));
    }
    const auto covered = hn::And(inside, hn::Gt(cover, zero));
    const auto safe_cover = hn::IfThenElse(covered, cover, one);
    const auto below = hn::Min(hn::Max(hn::Add(hn::Mul(hn::Sub(dot(f.rz), hn::Div(cover_depth, safe_cover)),
                                                       set(float(1.0 / kCanopySoftness))),
                                              set(0.5f)),
                                       zero),
                               one);
    // Vertical gap fraction g -> diffuse (cosine-weighted hemisphere) transmittance 2∫g^(1/μ)μ dμ ≈ g^1.5.
    const auto gap = hn::Sub(one, hn::Mul(hn::Mul(set(kCanopyDensity), cover), below));
    const auto share = hn::Sub(one, hn::Mul(gap, hn::Sqrt(gap)));
    hn::Store(hn::IfThenElseZero(covered, share), d, tmp);
    std::copy(tmp, tmp + n, out + first);
  }
}

}  // namespace silva::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace silva::render {

HWY_EXPORT(CanopyRowImpl);

void canopy_share_row(const CanopyMap& map, const Vec3f* positions, size_t count, float* out) {
  if (count > 0) HWY_DYNAMIC_DISPATCH(CanopyRowImpl)(map, positions, count, out);
}

}  // namespace silva::render
#endif  // HWY_ONCE
