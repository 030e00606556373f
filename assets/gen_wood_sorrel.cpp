#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "assets/generators.hpp"
#include "assets/shrub_parts.hpp"
#include "assets/strips.hpp"
#include "assets/understory_masks.hpp"

namespace silva::assets {

namespace {
/// Width of a stalk card, metres (its mask's line is a third to a quarter of it: a 1-1.5 mm petiole).
constexpr float kStalkCardWidth = 0.004f;
}  // namespace

GeneratedAsset generate_wood_sorrel(Rng& rng) {
  constexpr float kPi = std::numbers::pi_v<float>;
  const float height = rng.range(0.05f, 0.13f);  // the tallest leaf's stalk
  const float spread = rng.range(0.12f, 0.32f);  // patch radius
  const int count = kMinWoodSorrelLeaves + int(rng.below(51));
  std::vector<std::pair<Vec3f, Vec3f>> stalks;  // base, top
  for (int i = 0; i < count; ++i) {
    const float az = rng.range(0.0f, 2.0f * kPi);
    const Vec3f base = spread * std::sqrt(rng.uniform()) * horizontal(az) - Vec3f(0, 0, 0.005f);
    const float h = height * rng.range(0.55f, 1.0f), lean = h * rng.range(0.05f, 0.4f);
    stalks.emplace_back(base, base + Vec3f(0, 0, h) + lean * horizontal(az + rng.range(-0.6f, 0.6f)));
  }
  MeshBuilder b;
  b.begin_part(Role::GroundVegetation, Material::Herb, herb_stalk_mask(), true);
  for (const auto& [base, top] : stalks)
    add_card(b, 0.5f * (base + top), 0.5f * kStalkCardWidth * horizontal(rng.range(0.0f, 2.0f * kPi)), 0.5f * (top - base));
  b.begin_part(Role::GroundVegetation, Material::Herb, wood_sorrel_leaf_mask(), true);
  for (const auto& stalk : stalks) {  // the leaf spreads flat atop its stalk, tilted a little
    const float across = rng.range(kWoodSorrelLeafSpan[0], kWoodSorrelLeafSpan[1]);
    add_leaf_card(b, rng, stalk.second, Vec3f::UnitZ(), 0.35f, 0.5f * across / kWoodSorrelLeafFill);
  }
  return {b.finish(), Role::GroundVegetation, CollisionProxy{}};
}

}  // namespace silva::assets
