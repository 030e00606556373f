#include "assets/alpha_masks.hpp"

#include <vector>

#include "assets/mask_strokes.hpp"

namespace silva::assets {

namespace {

/// Rasterises the union of strokes into a shared kMaskSize x kMaskSize mask.
std::shared_ptr<const AlphaMask> rasterise(const std::vector<Stroke>& strokes) {
  return rasterise_strokes(strokes, kMaskSize, kMaskSize);
}

}  // namespace

std::shared_ptr<const AlphaMask> bare_twig_mask() {
  static const auto mask = [] {
    std::vector<Stroke> s = {{{0.5f, 1.0f}, {0.48f, 0.04f}, 0.03f, 0.012f}};
    for (int i = 0; i < 6; ++i) {
      const float side = i % 2 ? 1.0f : -1.0f;
      const Vec2f a(0.5f, 0.85f - 0.13f * float(i));
      const Vec2f b = stroke_towards(a, side * 40.0f, 0.4f - 0.04f * float(i));
      s.push_back({a, b, 0.018f, 0.008f});
      const Vec2f m = a + 0.5f * (b - a);
      s.push_back({m, stroke_towards(m, side * 10.0f, 0.16f), 0.012f, 0.006f});
      s.push_back({m, stroke_towards(m, side * 75.0f, 0.14f), 0.012f, 0.006f});
    }
    return rasterise(s);
  }();
  return mask;
}

}  // namespace silva::assets
