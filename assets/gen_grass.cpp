#include <cmath>
#include <numbers>

#include "assets/alpha_masks.hpp"
#include "assets/generators.hpp"

namespace silva::assets {

GeneratedAsset generate_grass(Rng& rng) {
  constexpr float kPi = std::numbers::pi_v<float>;
  const float height = rng.range(0.3f, 0.6f);
  const int cards = 5 + int(rng.below(3));
  MeshBuilder b;
  b.begin_part(Role::GroundVegetation, Material::Grass, grass_blades_mask(), true);
  for (int i = 0; i < cards; ++i) {
    const float yaw = kPi * (float(i) + rng.range(-0.25f, 0.25f)) / float(cards);
    const Vec3f base(rng.range(-0.05f, 0.05f), rng.range(-0.05f, 0.05f), -0.02f);
    const Vec3f up = Vec3f(rng.range(-0.2f, 0.2f), rng.range(-0.2f, 0.2f), 1.0f).normalized();
    const float h = height * rng.range(0.85f, 1.0f);
    add_card(b, base + 0.5f * h * up, rng.range(0.12f, 0.2f) * Vec3f(std::cos(yaw), std::sin(yaw), 0), 0.5f * h * up);
  }
  return {b.finish(), Role::GroundVegetation, CollisionProxy{}};
}

}  // namespace silva::assets
