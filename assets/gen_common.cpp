#include <cmath>
#include <numbers>

#include "assets/generators.hpp"

namespace silva::assets {

CollisionProxy cylinder_proxy(float r, float h) {
  CollisionProxy p;
  p.shape = CollisionProxy::Shape::Cylinder;
  p.center = Vec3f(0, 0, 0.5f * h);
  p.radius = r;
  p.height = h;
  return p;
}

Vec3f random_direction(Rng& rng) {
  const float z = rng.range(-1.0f, 1.0f);
  const float a = rng.range(0.0f, 2.0f * std::numbers::pi_v<float>);
  const float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
  return Vec3f(s * std::cos(a), s * std::sin(a), z);
}

void add_card_blob(MeshBuilder& b, Rng& rng, const Vec3f& center, const Vec3f& radii, int count, float half) {
  for (int i = 0; i < count; ++i) {
    const Vec3f d = random_direction(rng);
    const float shell = rng.range(0.55f, 1.0f);  // most cards near the surface of the blob
    const Vec3f c = center + (shell * d).cwiseProduct(radii);
    Vec3f n = d + 0.8f * random_direction(rng);
    n = n.norm() > 1e-3f ? Vec3f(n.normalized()) : d;
    Vec3f u, v;
    perpendicular_frame(n, u, v);
    const float spin = rng.range(0.0f, 2.0f * std::numbers::pi_v<float>);
    const Vec3f right = std::cos(spin) * u + std::sin(spin) * v;
    const float s = half * rng.range(0.8f, 1.2f);
    add_card(b, c, s * right, s * n.cross(right));
  }
}

}  // namespace silva::assets
