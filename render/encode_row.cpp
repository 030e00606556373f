// The per-target kernel of encode_srgb8_row (render/post.hpp), compiled once per Highway target
// (foreach_target) and chosen at run time. Only correctly rounded operations in the scalar
// functions' order (no MulAdd), so every target writes the bytes noisy_signal + tonemap_aces +
// linear_to_srgb8 give.
#include <algorithm>

#include "render/post.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/encode_row.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace silva::render::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

/// encode_srgb8_row for one target: the 3 * count channel values as one flat run of lanes.
void EncodeRowImpl(const float* radiance, size_t count, const RowExposure& row, uint8_t* out) {
  const hn::ScalableTag<float> d;
  const hn::RebindToSigned<decltype(d)> di;
  const size_t N = hn::Lanes(d), values = 3 * count;
  const uint8_t* table = srgb8_table();
  const auto zero = hn::Zero(d), one = hn::Set(d, 1.0f);
  const auto electrons_per_unit = hn::Set(d, row.noise.electrons_per_unit);
  const auto unit_per_electron = hn::Set(d, row.noise.unit_per_electron);
  const auto read_variance = hn::Set(d, row.noise.read_variance);
  HWY_ALIGN int32_t index[hn::MaxLanes(d)];
  for (size_t first = 0; first < values; first += N) {
    const size_t n = std::min(N, values - first);
    const auto load = [&](const float* p) {
      if (n == N) return hn::LoadU(d, p + first);
      HWY_ALIGN float tail[hn::MaxLanes(d)] = {};
      std::copy(p + first, p + first + n, tail);
      return hn::Load(d, tail);
    };
    auto x = hn::Mul(load(radiance), row.scales ? load(row.scales) : hn::Set(d, row.exposure));
    if (row.normals) {
      const auto electrons = hn::Mul(hn::Min(hn::Max(x, zero), one), electrons_per_unit);
      const auto sigma = hn::Mul(hn::Sqrt(hn::Add(electrons, read_variance)), unit_per_electron);
      x = hn::Add(x, hn::Mul(load(row.normals), sigma));
    }
    x = hn::Max(x, zero);
    const auto num = hn::Mul(x, hn::Add(hn::Mul(hn::Set(d, 2.51f), x), hn::Set(d, 0.03f)));
    const auto den = hn::Add(hn::Mul(x, hn::Add(hn::Mul(hn::Set(d, 2.43f), x), hn::Set(d, 0.59f))), hn::Set(d, 0.14f));
    const auto c = hn::Max(hn::Min(hn::Mul(hn::Div(num, den), hn::Set(d, kToneGain)), one), zero);
    const auto scaled = hn::Add(hn::Mul(c, hn::Set(d, float(kSrgbTableSize - 1))), hn::Set(d, 0.5f));
    hn::Store(hn::ConvertTo(di, scaled), di, index);
    for (size_t k = 0; k < n; ++k) out[first + k] = table[index[k]];
  }
}

/// The target this copy of the kernel was compiled for.
int64_t EncodeTargetImpl() { return HWY_TARGET; }

}  // namespace silva::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace silva::render {

HWY_EXPORT(EncodeRowImpl);
HWY_EXPORT(EncodeTargetImpl);

void encode_srgb8_row(const float* radiance, size_t count, const RowExposure& row, uint8_t* out) {
  if (count > 0) HWY_DYNAMIC_DISPATCH(EncodeRowImpl)(radiance, count, row, out);
}

int64_t encode_simd_target() { return HWY_DYNAMIC_DISPATCH(EncodeTargetImpl)(); }

}  // namespace silva::render
#endif  // HWY_ONCE
