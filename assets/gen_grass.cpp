#include <cmath>
#include <memory>
#include <numbers>

#include "assets/generators.hpp"
#include "assets/strips.hpp"
#include "assets/understory_masks.hpp"

namespace silva::assets {

namespace {

/// Adds `cards` curved tuft cards spread around the clump centre: each a 2-segment strip that
/// leans outward and bends further towards its top; heights in [0.6, 1] of `height`.
void add_tuft_cards(MeshBuilder& b, Rng& rng, int cards, float height, float half_width) {
  constexpr float kPi = std::numbers::pi_v<float>;
  const float phase = rng.range(0.0f, kPi);
  for (int i = 0; i < cards; ++i) {
    const float yaw = phase + kPi * (float(i) + rng.range(-0.3f, 0.3f)) / float(cards);
    const float lean_az = yaw + 0.5f * kPi + (rng.uniform() < 0.5f ? 0.0f : kPi);
    const Vec3f out = horizontal(lean_az);
    const float h = height * rng.range(0.6f, 1.0f), lean = rng.range(0.05f, 0.3f), bend = rng.range(0.1f, 0.35f);
    const Vec3f base = rng.range(0.0f, 0.04f) * horizontal(rng.range(0.0f, 2.0f * kPi)) - Vec3f(0, 0, 0.01f);
    const Vec3f mid = base + 0.5f * h * Vec3f(0, 0, 1) + 0.5f * h * lean * out;
    const Vec3f top = base + h * Vec3f(0, 0, 1 - 0.5f * bend) + h * (lean + bend) * out;
    const StripNode spine[] = {{base, 0.8f * half_width}, {mid, half_width}, {top, 1.1f * half_width}};
    add_strip(b, spine, horizontal(yaw));
  }
}

}  // namespace

GeneratedAsset generate_grass(Rng& rng) {
  const float height = rng.range(0.1f, 0.35f);
  MeshBuilder b;
  b.begin_part(Role::GroundVegetation, Material::Grass, grass_tuft_mask(), true);
  add_tuft_cards(b, rng, 6 + int(rng.below(5)), height, height * rng.range(0.3f, 0.45f));
  return {b.finish(), Role::GroundVegetation, CollisionProxy{}};
}

GeneratedAsset generate_tall_grass(Rng& rng) {
  const float height = rng.range(0.35f, 0.8f);
  MeshBuilder b;
  b.begin_part(Role::GroundVegetation, Material::Grass, grass_tuft_mask(), true);
  add_tuft_cards(b, rng, 6 + int(rng.below(4)), 0.75f * height, height * rng.range(0.18f, 0.26f));
  b.begin_part(Role::GroundVegetation, Material::Grass, grass_seed_mask(), true);
  add_tuft_cards(b, rng, 2 + int(rng.below(3)), height, height * rng.range(0.15f, 0.2f));
  return {b.finish(), Role::GroundVegetation, CollisionProxy{}};
}

}  // namespace silva::assets
