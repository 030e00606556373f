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

/// Leaves radiating from the card centre at the given angles.
std::vector<Stroke> radial_leaves(int count, float length, float width, float twist) {
  std::vector<Stroke> s;
  const Vec2f c(0.5f, 0.5f);
  for (int i = 0; i < count; ++i) {
    const float deg = twist + 360.0f * float(i) / float(count);
    const Vec2f a = towards(c, deg, 0.06f);
    s.push_back({a, towards(a, deg, length), width, 0, true});
  }
  return s;
}

}  // namespace

std::shared_ptr<const AlphaMask> leaf_cluster_mask() {
  static const auto mask = [] {
    auto s = radial_leaves(7, 0.40f, 0.09f, 10.0f);
    const auto inner = radial_leaves(5, 0.25f, 0.07f, 40.0f);
    s.insert(s.end(), inner.begin(), inner.end());
    return rasterise(s);
  }();
  return mask;
}

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

}  // namespace silva::assets
