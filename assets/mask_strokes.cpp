#include "assets/mask_strokes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace silva::assets {

bool stroke_covers(const Stroke& s, const Vec2f& p) {
  const Vec2f ab = s.b - s.a;
  const float t = std::clamp((p - s.a).dot(ab) / ab.squaredNorm(), 0.0f, 1.0f);
  const float d2 = (p - (s.a + t * ab)).squaredNorm();
  if (d2 > std::max(s.w0 * s.w0, s.w1 * s.w1)) return false;  // beyond the widest half-width: no profile needed
  float w = s.w0 + (s.w1 - s.w0) * t;
  if (s.shape != Stroke::Shape::Tapered)
    w = s.w0 * std::pow(std::sin(std::numbers::pi_v<float> * t), s.shape == Stroke::Shape::Pointed ? 0.7f : 0.35f);
  return d2 <= w * w;
}

std::shared_ptr<AlphaMask> rasterise_strokes(const std::vector<Stroke>& strokes, int width, int height) {
  auto mask = std::make_shared<AlphaMask>();
  mask->width = width;
  mask->height = height;
  mask->alpha.assign(size_t(width) * size_t(height), 0);
  const float scale = float(width);  // texel centres at ((x + 0.5) / width, (y + 0.5) / width)
  for (const Stroke& s : strokes) {
    // Texels whose centres may lie within the stroke's widest half-width of its segment.
    const float w = std::max(s.w0, s.w1);
    const auto first = [&](float lo, int n) { return std::clamp(int(std::floor(lo * scale - 0.5f)), 0, n); };
    const auto last = [&](float hi, int n) { return std::clamp(int(std::ceil(hi * scale - 0.5f)), -1, n - 1); };
    const int x0 = first(std::min(s.a.x(), s.b.x()) - w, width), x1 = last(std::max(s.a.x(), s.b.x()) + w, width);
    const int y0 = first(std::min(s.a.y(), s.b.y()) - w, height), y1 = last(std::max(s.a.y(), s.b.y()) + w, height);
    const Vec2f d = s.b - s.a;
    for (int y = y0; y <= y1; ++y) {
      // Only the texels of this row near the part of the segment within w of the row's centre line.
      const float py = (float(y) + 0.5f) / scale;
      int from = x0, to = x1;
      if (std::abs(d.y()) > 1e-6f) {
        const float ta = std::clamp((py - w - s.a.y()) / d.y(), 0.0f, 1.0f);
        const float tb = std::clamp((py + w - s.a.y()) / d.y(), 0.0f, 1.0f);
        const float xa = s.a.x() + ta * d.x(), xb = s.a.x() + tb * d.x();
        from = std::max(from, first(std::min(xa, xb) - w, width));
        to = std::min(to, last(std::max(xa, xb) + w, width));
      }
      for (int x = from; x <= to; ++x) {
        uint8_t& a = mask->alpha[size_t(y) * size_t(width) + size_t(x)];
        if (a == 0 && stroke_covers(s, Vec2f((float(x) + 0.5f) / scale, py))) a = s.alpha;
      }
    }
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
