// The per-target kernel is compiled once per Highway target (foreach_target) and chosen at run
// time. Every value is computed with correctly rounded float operations in one fixed order (no
// MulAdd), so all targets agree bit for bit.
#include "render/edge_aa_lanes.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/edge_aa_lanes.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace silva::render::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using VF = hn::Vec<DF>;

/// |a + b - 2 c|: the second difference across c.
VF second_difference(VF a, VF b, VF c) {
  return hn::Abs(hn::Sub(hn::Add(a, b), hn::Mul(hn::Set(DF(), 2.0f), c)));
}

size_t EdgeBlendsImpl(const float* up, const float* mid, const float* down, int begin, int end, const EdgeRow& out) {
  const DF df;
  const hn::RebindToSigned<DF> di;
  const int N = int(hn::Lanes(df));
  const VF two = hn::Set(df, 2.0f);
  size_t count = 0;
  for (int x = begin; x < end; x += N) {
    const auto load = [&](const float* row, int dx) { return hn::LoadU(df, row + x + dx); };
    const VF lc = load(mid, 0), ln = load(up, 0), ls = load(down, 0), le = load(mid, 1), lw = load(mid, -1);
    const VF hi = hn::Max(hn::Max(hn::Max(lc, ln), hn::Max(ls, le)), lw);
    const VF lo = hn::Min(hn::Min(hn::Min(lc, ln), hn::Min(ls, le)), lw);
    const VF contrast = hn::Sub(hi, lo);
    const VF threshold = hn::Max(hn::Set(df, kEdgeMinContrast), hn::Mul(hn::Set(df, kEdgeRelativeContrast), hi));
    const auto edge = hn::And(hn::Not(hn::Lt(contrast, threshold)), hn::RebindMask(df, hn::FirstN(di, size_t(end - x))));
    if (hn::AllFalse(df, edge)) continue;
    const VF lne = load(up, 1), lnw = load(up, -1), lse = load(down, 1), lsw = load(down, -1);
    // Luma change across rows (a horizontal edge) vs across columns (a vertical edge).
    const VF across_rows = hn::Add(hn::Add(hn::Mul(two, second_difference(ln, ls, lc)), second_difference(lne, lse, le)),
                                   second_difference(lnw, lsw, lw));
    const VF across_cols = hn::Add(hn::Add(hn::Mul(two, second_difference(le, lw, lc)), second_difference(lne, lnw, ln)),
                                   second_difference(lse, lsw, ls));
    // The neighbour across the edge that differs most, taken in the order north, south, east, west
    // (a later one only when strictly larger).
    const auto rows_first = hn::Ge(across_rows, across_cols), cols_first = hn::Ge(across_cols, across_rows);
    VF best = hn::Set(df, -1.0f);
    auto which = hn::Zero(di);
    const auto consider = [&](auto allowed, VF l, EdgeNeighbour n) {
      const VF diff = hn::Abs(hn::Sub(l, lc));
      const auto take = hn::And(allowed, hn::Gt(diff, best));
      best = hn::IfThenElse(take, diff, best);
      which = hn::IfThenElse(hn::RebindMask(di, take), hn::Set(di, int32_t(n)), which);
    };
    consider(rows_first, ln, EdgeNeighbour::North);
    consider(rows_first, ls, EdgeNeighbour::South);
    consider(cols_first, le, EdgeNeighbour::East);
    consider(cols_first, lw, EdgeNeighbour::West);
    // How much the pixel stands out from its neighbourhood, eased: 0 on smooth gradients, 1 on a spike.
    const VF cross = hn::Mul(two, hn::Add(hn::Add(hn::Add(ln, ls), le), lw));
    const VF sum = hn::Add(hn::Add(hn::Add(hn::Add(cross, lne), lnw), lse), lsw);
    const VF average = hn::Div(sum, hn::Set(df, 12.0f));
    const VF t = hn::Min(hn::Div(hn::Abs(hn::Sub(average, lc)), contrast), hn::Set(df, 1.0f));
    const VF eased = hn::Mul(hn::Mul(t, t), hn::Sub(hn::Set(df, 3.0f), hn::Mul(two, t)));
    const VF blend = hn::Mul(hn::Set(df, kEdgeMaxBlend), eased);
    const auto columns = hn::Add(hn::Iota(di, 0), hn::Set(di, x));
    const auto edge_i = hn::RebindMask(di, edge);
    hn::CompressBlendedStore(columns, edge_i, di, out.column + count);
    hn::CompressBlendedStore(blend, edge, df, out.blend + count);
    count += hn::CompressBlendedStore(which, edge_i, di, out.neighbour + count);
  }
  return count;
}

/// Lanes of this target.
size_t LanesImpl() { return hn::Lanes(DF()); }

}  // namespace silva::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace silva::render {

HWY_EXPORT(EdgeBlendsImpl);
HWY_EXPORT(LanesImpl);

size_t edge_lane_padding() { return HWY_DYNAMIC_DISPATCH(LanesImpl)(); }

size_t edge_blends_lanes(const float* up, const float* mid, const float* down, int begin, int end, const EdgeRow& out) {
  return HWY_DYNAMIC_DISPATCH(EdgeBlendsImpl)(up, mid, down, begin, end, out);
}

}  // namespace silva::render
#endif  // HWY_ONCE
