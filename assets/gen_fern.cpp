#include <cmath>
#include <numbers>

#include "assets/alpha_masks.hpp"
#include "assets/generators.hpp"

namespace silva::assets {

GeneratedAsset generate_fern(Rng& rng) {
  constexpr float kPi = std::numbers::pi_v<float>;
  const float height = rng.range(0.5f, 1.0f);
  const int fronds = 6 + int(rng.below(4));
  MeshBuilder b;
  b.begin_part(Role::GroundVegetation, Material::Fern, fern_frond_mask(), true);
  for (int i = 0; i < fronds; ++i) {
    const float az = 2.0f * kPi * (float(i) + rng.range(-0.3f, 0.3f)) / float(fronds);
    const float tilt = rng.range(0.5f, 0.9f);  // from vertical
    const float len = height * rng.range(0.85f, 1.0f) / std::cos(tilt);
    const Vec3f up(std::cos(az) * std::sin(tilt), std::sin(az) * std::sin(tilt), std::cos(tilt));
    const Vec3f right(-std::sin(az), std::cos(az), 0);
    add_card(b, 0.5f * len * up, 0.16f * len * right, 0.5f * len * up);
  }
  return {b.finish(), Role::GroundVegetation, CollisionProxy{}};
}

}  // namespace silva::assets
