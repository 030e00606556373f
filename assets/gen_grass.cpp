#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "assets/generators.hpp"
#include "assets/strips.hpp"
#include "assets/understory_masks.hpp"

namespace silva::assets {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

/// Adds one curved card of height h and half-width `half_width` from `base`, facing along `yaw`: a
/// 2-segment strip leaning by `lean` (of h) towards `out` and bending by `bend` further near its top.
void add_curved_card(MeshBuilder& b, const Vec3f& base, float yaw, const Vec3f& out, float h, float lean, float bend,
                     float half_width) {
  const Vec3f mid = base + 0.5f * h * Vec3f(0, 0, 1) + 0.5f * h * lean * out;
  const Vec3f top = base + h * Vec3f(0, 0, 1 - 0.5f * bend) + h * (lean + bend) * out;
  const StripNode spine[] = {{base, 0.8f * half_width}, {mid, half_width}, {top, 1.1f * half_width}};
  add_strip(b, spine, horizontal(yaw));
}

/// Adds `cards` curved tuft cards spread around the clump centre, leaning outward and bending further
/// towards their tops; heights in [0.6, 1] of `height`.
void add_tuft_cards(MeshBuilder& b, Rng& rng, int cards, float height, float half_width) {
  const float phase = rng.range(0.0f, kPi);
  for (int i = 0; i < cards; ++i) {
    const float yaw = phase + kPi * (float(i) + rng.range(-0.3f, 0.3f)) / float(cards);
    const float lean_az = yaw + 0.5f * kPi + (rng.uniform() < 0.5f ? 0.0f : kPi);
    const float h = height * rng.range(0.6f, 1.0f), lean = rng.range(0.05f, 0.3f), bend = rng.range(0.1f, 0.35f);
    const Vec3f base = rng.range(0.0f, 0.04f) * horizontal(rng.range(0.0f, 2.0f * kPi)) - Vec3f(0, 0, 0.01f);
    add_curved_card(b, base, yaw, horizontal(lean_az), h, lean, bend, half_width);
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

GeneratedAsset generate_grass_sward(Rng& rng) {
  const float height = rng.range(kGrassSwardHeight[0], kGrassSwardHeight[1]);
  const float spread = rng.range(kGrassSwardRadius[0], kGrassSwardRadius[1]);
  const float area = kPi * spread * spread;
  const int cards = std::max(kMinGrassSwardCards, int(std::lround(kGrassSwardCardsPerSquareMetre * area)));
  MeshBuilder b;
  b.begin_part(Role::GroundVegetation, Material::Grass, grass_sward_mask(), true);
  for (int i = 0; i < cards; ++i) {  // cards scattered over the patch, each facing its own way
    const Vec3f base = spread * std::sqrt(rng.uniform()) * horizontal(rng.range(0.0f, 2.0f * kPi)) - Vec3f(0, 0, 0.01f);
    const float yaw = rng.range(0.0f, kPi), lean_az = yaw + 0.5f * kPi + (rng.uniform() < 0.5f ? 0.0f : kPi);
    const float h = height * rng.range(0.7f, 1.0f), lean = rng.range(0.02f, 0.15f), bend = rng.range(0.05f, 0.2f);
    add_curved_card(b, base, yaw, horizontal(lean_az), h, lean, bend, 0.5f * kGrassSwardCardWidth);
  }
  return {b.finish(), Role::GroundVegetation, CollisionProxy{}};
}

}  // namespace silva::assets
