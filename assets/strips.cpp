#include "assets/strips.hpp"

#include <cmath>

namespace silva::assets {

void add_strip(MeshBuilder& b, std::span<const StripNode> spine, const Vec3f& side) {
  const size_t n = spine.size();
  std::vector<uint32_t> left(n), right(n);
  for (size_t i = 0; i < n; ++i) {
    const size_t lo = i == 0 ? 0 : i - 1, hi = i + 1 == n ? i : i + 1;
    const Vec3f t = (spine[hi].p - spine[lo].p).normalized();
    Vec3f s = side - t * t.dot(side);
    s = s.norm() > 1e-6f ? Vec3f(s.normalized()) : Vec3f(t.unitOrthogonal());
    const Vec3f normal = s.cross(t);
    const float v = 1.0f - float(i) / float(n - 1);
    left[i] = b.vertex(spine[i].p - spine[i].half_width * s, normal, Vec2f(0, v));
    right[i] = b.vertex(spine[i].p + spine[i].half_width * s, normal, Vec2f(1, v));
  }
  for (size_t i = 0; i + 1 < n; ++i) {
    b.triangle(left[i], right[i], right[i + 1]);
    b.triangle(left[i], right[i + 1], left[i + 1]);
  }
}

std::vector<Vec3f> bezier(const Vec3f& a, const Vec3f& c, const Vec3f& b, int segments) {
  std::vector<Vec3f> out;
  for (int i = 0; i <= segments; ++i) {
    const float t = float(i) / float(segments);
    out.push_back((1 - t) * (1 - t) * a + 2 * (1 - t) * t * c + t * t * b);
  }
  return out;
}

void add_ribbon_stem(MeshBuilder& b, std::span<const TubeNode> nodes) {
  const Vec3f t = (nodes.back().p - nodes.front().p).normalized();
  Vec3f u, v;
  perpendicular_frame(t, u, v);
  std::vector<StripNode> spine;
  for (const TubeNode& n : nodes) spine.push_back({n.p, n.r});
  add_strip(b, spine, u);
  add_strip(b, spine, v);
}

Vec3f horizontal(float az) { return Vec3f(std::cos(az), std::sin(az), 0.0f); }

}  // namespace silva::assets
