#include <cmath>
#include <numbers>
#include <vector>

#include "assets/generators.hpp"
#include "assets/strips.hpp"
#include "assets/understory_masks.hpp"

namespace silva::assets {

GeneratedAsset generate_wood_sorrel(Rng& rng) {
  constexpr float kPi = std::numbers::pi_v<float>;
  const float spread = rng.range(0.2f, 0.45f);  // patch radius
  const int leaves = 30 + int(rng.below(41));
  MeshBuilder b;
  b.begin_part(Role::GroundVegetation, Material::Fern, trefoil_leaf_mask(), true);
  std::vector<std::pair<Vec3f, Vec3f>> stalks;  // leaf centre, the leaf's right edge direction
  for (int i = 0; i < leaves; ++i) {
    const Vec3f at = spread * std::sqrt(rng.uniform()) * horizontal(rng.range(0.0f, 2.0f * kPi));
    const float height = rng.range(0.04f, 0.11f), half = rng.range(0.02f, 0.03f);
    // Level leaves, each tilted a little and spun about its stalk.
    const Vec3f normal = (Vec3f::UnitZ() + 0.25f * horizontal(rng.range(0.0f, 2.0f * kPi))).normalized();
    Vec3f u, v;
    perpendicular_frame(normal, u, v);
    const float spin = rng.range(0.0f, 2.0f * kPi);
    const Vec3f right = std::cos(spin) * u + std::sin(spin) * v;
    add_card(b, at + Vec3f(0, 0, height), half * right, half * normal.cross(right));
    stalks.emplace_back(at + Vec3f(0, 0, height), Vec3f(right.x(), right.y(), 0).normalized());
  }
  // Stalks: 2 mm strips from just below the floor up to each leaf's centre.
  b.begin_part(Role::GroundVegetation, Material::Fern, nullptr, true);
  for (const auto& [top, side] : stalks) {
    const float half_height = 0.5f * top.z() + 0.005f;
    add_card(b, Vec3f(top.x(), top.y(), top.z() - half_height), 0.001f * side, Vec3f(0, 0, half_height));
  }
  return {b.finish(), Role::GroundVegetation, CollisionProxy{}};
}

}  // namespace silva::assets
