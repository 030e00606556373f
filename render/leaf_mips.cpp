#include "render/leaf_mips.hpp"

#include <algorithm>
#include <cmath>

#include "render/materials.hpp"

namespace silva::render {

namespace {

/// Alpha in 128 … 254 whose leaf_brightness is nearest `brightness` (0.75 … 1.25).
uint8_t alpha_of_brightness(double brightness) {
  const double a = 128.0 + std::round((brightness - 0.75) / 0.5 * 126.0);
  return uint8_t(std::clamp(a, 128.0, 254.0));
}

}  // namespace

LeafMips LeafMips::of(const AlphaMask& mask) {
  // Sums of brightness and counts of opaque level-0 texels per texel of the current level.
  int w = mask.width, h = mask.height;
  std::vector<double> sum(size_t(w) * size_t(h), 0.0);
  std::vector<uint32_t> count(sum.size(), 0);
  for (size_t i = 0; i < sum.size(); ++i)
    if (mask.opaque_texel(int(i))) sum[i] = leaf_brightness(mask.alpha[i]), count[i] = 1;
  LeafMips mips;
  while (w % 2 == 0 && h % 2 == 0) {
    const int cw = w / 2, ch = h / 2;
    std::vector<double> coarse_sum(size_t(cw) * size_t(ch), 0.0);
    std::vector<uint32_t> coarse_count(coarse_sum.size(), 0);
    Level level{cw, ch, std::vector<uint8_t>(coarse_sum.size(), 0)};
    for (int y = 0; y < ch; ++y)
      for (int x = 0; x < cw; ++x) {
        const size_t c = size_t(y) * size_t(cw) + size_t(x);
        for (const size_t f : {size_t(2 * y) * size_t(w) + size_t(2 * x), size_t(2 * y) * size_t(w) + size_t(2 * x + 1),
                               size_t(2 * y + 1) * size_t(w) + size_t(2 * x), size_t(2 * y + 1) * size_t(w) + size_t(2 * x + 1)}) {
          coarse_sum[c] += sum[f];
          coarse_count[c] += count[f];
        }
        if (coarse_count[c] > 0) level.alpha[c] = alpha_of_brightness(coarse_sum[c] / double(coarse_count[c]));
      }
    mips.levels_.push_back(std::move(level));
    sum.swap(coarse_sum);
    count.swap(coarse_count);
    w = cw, h = ch;
  }
  return mips;
}

uint8_t LeafMips::alpha(const AlphaMask& mask, float u, float v, float texels_across) const {
  const int k = texels_across >= 2.0f ? std::min(std::ilogb(texels_across), coarse_levels()) : 0;
  const auto at = [&](const std::vector<uint8_t>& alpha, int width, int height) {
    return alpha[size_t(AlphaMask::texel(v, height)) * size_t(width) + size_t(AlphaMask::texel(u, width))];
  };
  if (k == 0) return at(mask.alpha, mask.width, mask.height);
  const Level& l = levels_[size_t(k - 1)];
  return at(l.alpha, l.width, l.height);
}

}  // namespace silva::render
