#include <algorithm>
#include <cmath>
#include <numbers>

#include "assets/generators.hpp"
#include "assets/strips.hpp"
#include "assets/shrub_parts.hpp"
#include "assets/understory_masks.hpp"

namespace silva::assets {

GeneratedAsset generate_bramble(Rng& rng) {
  constexpr float kPi = std::numbers::pi_v<float>;
  const float height = rng.range(0.5f, 1.5f);
  const int count = 6 + int(rng.below(7));
  std::vector<StemNodes> canes;
  float reach = 0;
  for (int i = 0; i < count; ++i) {
    // An arching cane: up from the crown, over, and (often) back down towards the ground.
    const float az = 2.0f * kPi * (float(i) + rng.range(-0.35f, 0.35f)) / float(count);
    const Vec3f base = rng.range(0.0f, 0.1f) * horizontal(az) - Vec3f(0, 0, 0.02f);
    const float span = height * rng.range(0.9f, 1.8f), arch = height * rng.range(0.75f, 1.0f);
    const Vec3f tip = base + span * horizontal(az) + Vec3f(0, 0, rng.range(0.0f, 0.4f) * arch);
    const Vec3f ctrl = base + 0.35f * span * horizontal(az) + Vec3f(0, 0, 2.0f * arch - 0.5f * (tip - base).z());
    canes.push_back(bent_stem(base, ctrl, tip, 0.007f, 0.003f, 6));
    reach = std::max(reach, tip.head<2>().norm());
  }
  MeshBuilder b;
  add_stems(b, canes, Role::Shrub, Material::BarkConifer);
  b.begin_part(Role::Shrub, Material::ShrubLeaves, bramble_leaf_mask(), true);
  const float leaf = rng.range(0.24f, 0.32f) * std::sqrt(height);
  for (const StemNodes& c : canes) {
    const int leaves = 18 + int(rng.below(10));
    for (int k = 0; k < leaves; ++k) {
      const float t = 0.15f + 0.85f * (float(k) + rng.uniform()) / float(leaves);
      const Vec3f at = stem_point(c, t), along = stem_point(c, t + 0.05f) - stem_point(c, t - 0.05f);
      Vec3f side = along.cross(Vec3f::UnitZ());
      side = side.norm() > 1e-4f ? Vec3f(side.normalized()) : Vec3f::UnitX();
      const Vec3f dir = (k % 2 ? side : Vec3f(-side)) + Vec3f(0, 0, rng.range(0.1f, 0.6f)) + 0.3f * random_direction(rng);
      add_stalked_card(b, rng, at, dir, leaf * rng.range(0.8f, 1.2f), 0.5f);
    }
  }
  return {b.finish(), Role::Shrub, cylinder_proxy(0.5f * reach, height)};
}

}  // namespace silva::assets
