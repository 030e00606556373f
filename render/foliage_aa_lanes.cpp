// The per-target kernel is compiled once per Highway target (foreach_target) and chosen at run
// time. Every value is computed with correctly rounded float operations in MaskBlendRows's order
// (no MulAdd), so all targets agree bit for bit.
#include "render/foliage_aa_lanes.hpp"

#include <limits>

#include "render/foliage_aa.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/foliage_aa_lanes.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace silva::render::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using VF = hn::Vec<DF>;

/// Running sums of one vector of pixels: their layer depths' bounds, blend weights and weighted sums.
struct LaneBlend {
  VF behind_from, in_front_to, wp;
  VF r, g, b, total;

  /// Adds the neighbours at columns x … x + lanes - 1 of row `q` with tent weight `tent`.
  void add(const BlendRowPlanes& q, int x, float tent) {
    const DF df;
    const VF dq = hn::LoadU(df, q.layer + x);
    const auto surface_behind = hn::And(hn::Lt(dq, hn::Set(df, std::numeric_limits<float>::infinity())), hn::Ge(dq, behind_from));
    const VF behind = hn::IfThenElseZero(surface_behind, wp);
    const VF in_front = hn::IfThenElseZero(hn::Le(dq, in_front_to), hn::LoadU(df, q.weight + x));
    const VF w = hn::Mul(hn::Mul(hn::Set(df, tent), hn::Max(behind, in_front)), hn::LoadU(df, q.tone + x));
    VF qr, qg, qb;
    hn::LoadInterleaved3(df, q.rgb + 3 * x, qr, qg, qb);
    r = hn::Add(r, hn::Mul(qr, w));
    g = hn::Add(g, hn::Mul(qg, w));
    b = hn::Add(b, hn::Mul(qb, w));
    total = hn::Add(total, w);
  }
};

int BlendInsideImpl(const BlendRowPlanes* rows, int begin, int end, float* out) {
  const DF df;
  const hn::Rebind<uint8_t, DF> d8;
  const hn::RebindToUnsigned<DF> du;
  const int N = int(hn::Lanes(df));
  const BlendRowPlanes &above = rows[0], &at = rows[1], &below = rows[2];
  int x = begin;
  for (; x + N <= end; x += N) {
    const auto near_of = [&](const BlendRowPlanes& p) { return hn::PromoteTo(du, hn::LoadU(d8, p.near + x)); };
    const auto near = hn::RebindMask(df, hn::Ne(hn::Or(hn::Or(near_of(at), near_of(above)), near_of(below)), hn::Zero(du)));
    VF pr, pg, pb;
    hn::LoadInterleaved3(df, at.rgb + 3 * x, pr, pg, pb);
    float* o = out + 3 * (x - begin);
    if (hn::AllFalse(df, near)) {
      hn::StoreInterleaved3(pr, pg, pb, df, o);
      continue;
    }
    const VF dp = hn::LoadU(df, at.layer + x);
    const VF own = hn::Mul(hn::Set(df, 4.0f), hn::LoadU(df, at.tone + x));
    LaneBlend s{hn::Mul(dp, hn::Set(df, 1.0f - kLayerTolerance)), hn::Mul(dp, hn::Set(df, 1.0f + kLayerTolerance)),
                hn::LoadU(df, at.weight + x), hn::Mul(pr, own), hn::Mul(pg, own), hn::Mul(pb, own), own};
    s.add(above, x, 2.0f);
    s.add(at, x - 1, 2.0f);
    s.add(at, x + 1, 2.0f);
    s.add(below, x, 2.0f);
    s.add(above, x - 1, 1.0f);
    s.add(above, x + 1, 1.0f);
    s.add(below, x - 1, 1.0f);
    s.add(below, x + 1, 1.0f);
    hn::StoreInterleaved3(hn::IfThenElse(near, hn::Div(s.r, s.total), pr), hn::IfThenElse(near, hn::Div(s.g, s.total), pg),
                          hn::IfThenElse(near, hn::Div(s.b, s.total), pb), df, o);
  }
  return x;
}

}  // namespace silva::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace silva::render {

HWY_EXPORT(BlendInsideImpl);

int blend_inside_lanes(const BlendRowPlanes rows[3], int begin, int end, float* out) {
  return HWY_DYNAMIC_DISPATCH(BlendInsideImpl)(rows, begin, end, out);
}

}  // namespace silva::render
#endif  // HWY_ONCE
