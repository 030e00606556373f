#include "assets/alpha_masks.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "assets/mask_strokes.hpp"

namespace silva::assets {

namespace {

/// Rasterises the union of strokes into a shared kMaskSize x kMaskSize mask.
std::shared_ptr<const AlphaMask> rasterise(const std::vector<Stroke>& strokes) {
  return rasterise_strokes(strokes, kMaskSize, kMaskSize);
}

/// A twig along v (base at v = 1) with `count` alternate pointed leaves `len` long, `width` wide,
/// at `deg` from the twig; each leaf gets `lobes` pairs of small side lobes (oak).
std::vector<Stroke> leafy_twig(int count, float len, float width, float deg, int lobes) {
  std::vector<Stroke> s = {{{0.5f, 1.0f}, {0.5f, 0.06f}, 0.018f, 0.01f}};
  for (int i = 0; i < count; ++i) {
    const float f = float(i) / float(count - 1);
    const Vec2f a(0.5f, 0.9f - 0.78f * f);
    const float side = i % 2 ? 1.0f : -1.0f, l = len * (1.0f - 0.3f * f);
    const Vec2f b = stroke_towards(a, side * deg * (1.0f - 0.4f * f), l);
    s.push_back({a, b, width, 0, Stroke::Shape::Pointed});
    for (int k = 1; k <= lobes; ++k) {
      const Vec2f m = a + (float(k) / float(lobes + 1)) * (b - a);
      for (float lr : {-1.0f, 1.0f})
        s.push_back({m, stroke_towards(m, side * deg * (1.0f - 0.4f * f) + lr * 70.0f, 0.55f * width + 0.3f * width * float(lobes - k)),
                     0.45f * width, 0, Stroke::Shape::Pointed});
    }
  }
  return s;
}

}  // namespace

std::shared_ptr<const AlphaMask> needle_spray_mask() {
  static const auto mask = [] {
    std::vector<Stroke> s = {{{0.5f, 1.0f}, {0.5f, 0.02f}, 0.025f, 0.01f}};
    for (int i = 0; i < 16; ++i) {
      const float y = 0.95f - 0.058f * float(i);
      const float len = 0.42f * (1.0f - 0.04f * float(i));
      for (float side : {-1.0f, 1.0f})
        s.push_back({{0.5f, y}, stroke_towards({0.5f, y}, side * 55.0f, len), 0.018f, 0.008f});
    }
    return rasterise(s);
  }();
  return mask;
}

std::shared_ptr<const AlphaMask> pine_tuft_mask() {
  static const auto mask = [] {
    std::vector<Stroke> s = {{{0.5f, 1.0f}, {0.5f, 0.5f}, 0.03f, 0.02f}};
    for (int i = 0; i < 23; ++i) {
      const float deg = -66.0f + 6.0f * float(i);
      const Vec2f a = stroke_towards({0.5f, 0.62f}, deg, 0.05f);
      s.push_back({a, stroke_towards(a, deg, 0.42f - 0.1f * std::abs(deg) / 66.0f), 0.016f, 0.008f});
    }
    return rasterise(s);
  }();
  return mask;
}

std::shared_ptr<const AlphaMask> larch_tuft_mask() {
  static const auto mask = [] {
    std::vector<Stroke> s = {{{0.5f, 1.0f}, {0.5f, 0.05f}, 0.02f, 0.01f}};
    for (int i = 0; i < 7; ++i) {
      const float side = i % 2 ? 1.0f : -1.0f;
      const Vec2f c(0.5f + side * 0.12f, 0.88f - 0.12f * float(i));
      for (int k = 0; k < 9; ++k) s.push_back({c, stroke_towards(c, -80.0f + 20.0f * float(k), 0.13f), 0.014f, 0.006f});
    }
    return rasterise(s);
  }();
  return mask;
}

std::shared_ptr<const AlphaMask> beech_leaves_mask() {
  static const auto mask = rasterise(leafy_twig(9, 0.34f, 0.1f, 65.0f, 0));
  return mask;
}

std::shared_ptr<const AlphaMask> birch_leaves_mask() {
  static const auto mask = rasterise(leafy_twig(10, 0.24f, 0.075f, 50.0f, 0));
  return mask;
}

std::shared_ptr<const AlphaMask> oak_leaves_mask() {
  static const auto mask = rasterise(leafy_twig(7, 0.36f, 0.08f, 60.0f, 2));
  return mask;
}

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
