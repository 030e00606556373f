#include "assets/shrub_parts.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "assets/generators.hpp"
#include "assets/strips.hpp"

namespace silva::assets {

void add_stems(MeshBuilder& b, const std::vector<StemNodes>& stems, Role role, Material material) {
  b.begin_part(role, material);
  std::vector<size_t> thick(stems.size(), 0);  // nodes drawn as a tube, per stem
  for (size_t s = 0; s < stems.size(); ++s) {
    while (thick[s] < stems[s].size() && stems[s][thick[s]].r >= kMinTubeRadius) ++thick[s];
    if (thick[s] >= 2) add_tube(b, std::span(stems[s]).first(thick[s]), 6);
  }
  b.begin_part(role, material, nullptr, true);
  for (size_t s = 0; s < stems.size(); ++s) {
    const size_t first = thick[s] >= 2 ? thick[s] - 1 : 0;  // ribbons continue where the tube ends
    if (stems[s].size() - first >= 2) add_ribbon_stem(b, std::span(stems[s]).subspan(first));
  }
}

Vec3f stem_point(const StemNodes& stem, float t) {
  const float x = std::clamp(t, 0.0f, 1.0f) * float(stem.size() - 1);
  const size_t i = std::min(size_t(x), stem.size() - 2);
  const float f = x - float(i);
  return (1 - f) * stem[i].p + f * stem[i + 1].p;
}

StemNodes bent_stem(const Vec3f& a, const Vec3f& c, const Vec3f& b, float r0, float r1, int segments) {
  StemNodes out;
  const std::vector<Vec3f> pts = bezier(a, c, b, segments);
  for (size_t i = 0; i < pts.size(); ++i) {
    const float f = float(i) / float(pts.size() - 1);
    out.push_back({pts[i], r0 + (r1 - r0) * f});
  }
  return out;
}

void add_leaf_card(MeshBuilder& b, Rng& rng, const Vec3f& center, const Vec3f& facing, float spread, float half) {
  Vec3f n = facing.normalized() + spread * random_direction(rng);
  n = n.norm() > 1e-3f ? Vec3f(n.normalized()) : Vec3f::UnitZ();
  Vec3f u, v;
  perpendicular_frame(n, u, v);
  const float spin = rng.range(0.0f, 2.0f * std::numbers::pi_v<float>);
  const Vec3f right = std::cos(spin) * u + std::sin(spin) * v;
  const float s = half * rng.range(0.8f, 1.2f);
  add_card(b, center, s * right, s * n.cross(right));
}

void add_stalked_card(MeshBuilder& b, Rng& rng, const Vec3f& base, const Vec3f& dir, float len, float roll) {
  const Vec3f up = dir.normalized();
  Vec3f side = up.cross(Vec3f::UnitZ());
  side = side.norm() > 1e-3f ? Vec3f(side.normalized()) : Vec3f::UnitX();
  const float r = rng.range(-roll, roll);
  const Vec3f normal = side.cross(up);
  const Vec3f right = std::cos(r) * side + std::sin(r) * normal;
  add_card(b, base + 0.5f * len * up, 0.5f * len * right, 0.5f * len * up);
}

}  // namespace silva::assets
