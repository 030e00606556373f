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

}  // namespace silva::assets
