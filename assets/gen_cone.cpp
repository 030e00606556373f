#include <cmath>
#include <numbers>

#include "assets/generators.hpp"
#include "assets/strips.hpp"
#include "assets/wood_parts.hpp"

namespace silva::assets {

GeneratedAsset generate_cone(Rng& rng) {
  constexpr float kPi = std::numbers::pi_v<float>;
  constexpr int kRows = 10, kAround = 12;
  const bool spruce = rng.uniform() < 0.6f;  // spruce: long and slim; pine: short and ovoid
  const float len = spruce ? rng.range(0.08f, 0.15f) : rng.range(0.04f, 0.07f);
  const float radius = len * (spruce ? rng.range(0.17f, 0.22f) : rng.range(0.3f, 0.4f));
  const float az = rng.range(0.0f, 2.0f * kPi), twist = rng.range(0.0f, 2.0f * kPi);
  const Vec3f axis = horizontal(az), u = Vec3f::UnitZ().cross(axis).normalized();
  std::vector<Vec3f> p;
  for (int i = 0; i < kRows; ++i) {
    const float f = float(i) / float(kRows - 1);
    const float profile = std::max(0.2f, std::pow(std::sin(kPi * (0.05f + 0.9f * f)), 0.7f) * (1.0f - 0.3f * f));
    std::vector<float> radii(kAround);
    for (int k = 0; k < kAround; ++k) {  // scales in a spiral: alternate bumps shifting per row
      const float a = 2.0f * kPi * float(k) / float(kAround);
      radii[size_t(k)] = radius * profile * (1.0f + 0.18f * std::max(0.0f, std::cos(6.0f * a + 2.4f * float(i) + twist)));
    }
    const Vec3f c = (f - 0.5f) * len * axis + Vec3f(0, 0, 0.9f * radius);
    const auto ring = ring_points(c, axis, u, radii);
    p.insert(p.end(), ring.begin(), ring.end());
  }
  MeshBuilder b;
  b.begin_part(Role::Ground, Material::BarkConifer);
  add_ring_grid(b, p, kRows, kAround);
  std::vector<Vec3f> start(p.rbegin() + (kRows - 1) * kAround, p.rend());
  add_end_cap(b, rng, start, -axis, 0.0f);
  add_end_cap(b, rng, std::span<const Vec3f>(p.data() + (kRows - 1) * kAround, kAround), axis, 0.0f);
  return {b.finish(), Role::Ground, CollisionProxy{}};
}

}  // namespace silva::assets
