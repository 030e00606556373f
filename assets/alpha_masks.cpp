#include "assets/alpha_masks.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace silva::assets {

namespace {

/// A stroke from a to b (texture units) whose half-width goes from w0 to w1; a pointed stroke
/// is widest in the middle and zero at both ends (a leaf).
struct Stroke {
  Vec2f a, b;
  float w0, w1;
  bool pointed = false;
};

/// True when point p lies inside the stroke.
bool inside(const Stroke& s, const Vec2f& p) {
  const Vec2f ab = s.b - s.a;
  const float t = std::clamp((p - s.a).dot(ab) / ab.squaredNorm(), 0.0f, 1.0f);
  const float w = s.pointed ? s.w0 * std::pow(std::sin(std::numbers::pi_v<float> * t), 0.7f)
                            : s.w0 + (s.w1 - s.w0) * t;
  return (p - (s.a + t * ab)).norm() <= w;
}

/// Rasterises the union of strokes at texel centres into a shared mask.
std::shared_ptr<const AlphaMask> rasterise(const std::vector<Stroke>& strokes) {
  auto mask = std::make_shared<AlphaMask>();
  mask->width = mask->height = kMaskSize;
  mask->alpha.assign(size_t(kMaskSize) * kMaskSize, 0);
  for (int y = 0; y < kMaskSize; ++y)
    for (int x = 0; x < kMaskSize; ++x) {
      const Vec2f p((float(x) + 0.5f) / kMaskSize, (float(y) + 0.5f) / kMaskSize);
      if (std::any_of(strokes.begin(), strokes.end(), [&](const Stroke& s) { return inside(s, p); }))
        mask->alpha[size_t(y) * kMaskSize + size_t(x)] = 255;
    }
  return mask;
}

/// A point at angle `deg` (0 = up the card, positive = right) and distance `len` from `from`.
Vec2f towards(const Vec2f& from, float deg, float len) {
  const float a = deg * std::numbers::pi_v<float> / 180.0f;
  return from + len * Vec2f(std::sin(a), -std::cos(a));
}

/// A twig along v (base at v = 1) with `count` alternate pointed leaves `len` long, `width` wide,
/// at `deg` from the twig; each leaf gets `lobes` pairs of small side lobes (oak).
std::vector<Stroke> leafy_twig(int count, float len, float width, float deg, int lobes) {
  std::vector<Stroke> s = {{{0.5f, 1.0f}, {0.5f, 0.06f}, 0.018f, 0.01f}};
  for (int i = 0; i < count; ++i) {
    const float f = float(i) / float(count - 1);
    const Vec2f a(0.5f, 0.9f - 0.78f * f);
    const float side = i % 2 ? 1.0f : -1.0f, l = len * (1.0f - 0.3f * f);
    const Vec2f b = towards(a, side * deg * (1.0f - 0.4f * f), l);
    s.push_back({a, b, width, 0, true});
    for (int k = 1; k <= lobes; ++k) {
      const Vec2f m = a + (float(k) / float(lobes + 1)) * (b - a);
      for (float lr : {-1.0f, 1.0f})
        s.push_back({m, towards(m, side * deg * (1.0f - 0.4f * f) + lr * 70.0f, 0.55f * width + 0.3f * width * float(lobes - k)),
                     0.45f * width, 0, true});
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
        s.push_back({{0.5f, y}, towards({0.5f, y}, side * 55.0f, len), 0.018f, 0.008f});
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
      const Vec2f a = towards({0.5f, 0.62f}, deg, 0.05f);
      s.push_back({a, towards(a, deg, 0.42f - 0.1f * std::abs(deg) / 66.0f), 0.016f, 0.008f});
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
      for (int k = 0; k < 9; ++k) s.push_back({c, towards(c, -80.0f + 20.0f * float(k), 0.13f), 0.014f, 0.006f});
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
      const Vec2f b = towards(a, side * 40.0f, 0.4f - 0.04f * float(i));
      s.push_back({a, b, 0.018f, 0.008f});
      const Vec2f m = a + 0.5f * (b - a);
      s.push_back({m, towards(m, side * 10.0f, 0.16f), 0.012f, 0.006f});
      s.push_back({m, towards(m, side * 75.0f, 0.14f), 0.012f, 0.006f});
    }
    return rasterise(s);
  }();
  return mask;
}

}  // namespace silva::assets
