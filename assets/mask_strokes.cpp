#include "assets/mask_strokes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace silva::assets {

bool stroke_covers(const Stroke& s, const Vec2f& p) {
  const Vec2f ab = s.b - s.a;
  const float t = std::clamp((p - s.a).dot(ab) / ab.squaredNorm(), 0.0f, 1.0f);
  float w = s.w0 + (s.w1 - s.w0) * t;
  if (s.shape != Stroke::Shape::Tapered)
    w = s.w0 * std::pow(std::sin(std::numbers::pi_v<float> * t), s.shape == Stroke::Shape::Pointed ? 0.7f : 0.35f);
  return (p - (s.a + t * ab)).squaredNorm() <= w * w;
}

std::shared_ptr<const AlphaMask> rasterise_strokes(const std::vector<Stroke>& strokes, int width, int height) {
  auto mask = std::make_shared<AlphaMask>();
  mask->width = width;
  mask->height = height;
  mask->alpha.assign(size_t(width) * size_t(height), 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Vec2f p((float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(width));
      if (std::any_of(strokes.begin(), strokes.end(), [&](const Stroke& s) { return stroke_covers(s, p); }))
        mask->alpha[size_t(y) * size_t(width) + size_t(x)] = 255;
    }
  return mask;
}

Vec2f stroke_towards(const Vec2f& from, float deg, float len) {
  const float a = deg * std::numbers::pi_v<float> / 180.0f;
  return from + len * Vec2f(std::sin(a), -std::cos(a));
}

void add_leaf_strokes(std::vector<Stroke>& s, const Vec2f& base, float deg, float len, float half, int teeth) {
  const Vec2f tip = stroke_towards(base, deg, len);
  s.push_back({base, tip, half, 0, Stroke::Shape::Round});
  for (int k = 0; k < teeth; ++k) {
    const float t = 0.25f + 0.6f * (float(k) + 0.5f) / float(teeth);
    const float w = half * std::pow(std::sin(std::numbers::pi_v<float> * t), 0.35f);
    const Vec2f on = base + t * (tip - base);
    for (float side : {-1.0f, 1.0f}) {
      const Vec2f edge = stroke_towards(on, deg + side * 90.0f, 0.8f * w);
      s.push_back({edge, stroke_towards(edge, deg + side * 40.0f, 0.45f * w), 0.18f * w, 0, Stroke::Shape::Pointed});
    }
  }
}

}  // namespace silva::assets
