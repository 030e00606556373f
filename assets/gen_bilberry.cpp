#include <algorithm>
#include <cmath>
#include <numbers>

#include "assets/generators.hpp"
#include "assets/strips.hpp"
#include "assets/shrub_parts.hpp"
#include "assets/understory_masks.hpp"

namespace silva::assets {

GeneratedAsset generate_bilberry(Rng& rng) {
  constexpr float kPi = std::numbers::pi_v<float>;
  const float height = rng.range(0.2f, 0.5f);
  const float spread = height * rng.range(0.8f, 1.5f);  // patch radius
  const int count = 14 + int(rng.below(14));
  std::vector<StemNodes> stems;
  float reach = 0;
  for (int i = 0; i < count; ++i) {
    const float az = rng.range(0.0f, 2.0f * kPi);
    const float from = spread * 0.6f * std::sqrt(rng.uniform());
    const Vec3f base = from * horizontal(az) - Vec3f(0, 0, 0.01f);
    const float h = height * rng.range(0.55f, 0.95f), out = rng.range(0.1f, 0.45f) * height;
    const Vec3f tip = base + Vec3f(0, 0, h) + out * horizontal(az + rng.range(-0.5f, 0.5f));
    const Vec3f ctrl = base + Vec3f(0, 0, 0.6f * h) + 0.2f * out * horizontal(az);
    stems.push_back(bent_stem(base, ctrl, tip, 0.003f, 0.0015f, 2));
    reach = std::max(reach, tip.head<2>().norm());
  }
  MeshBuilder b;
  add_stems(b, stems, Role::Shrub, Material::ShrubLeaves);
  b.begin_part(Role::Shrub, Material::ShrubLeaves, bilberry_leaves_mask(), true);
  for (const StemNodes& s : stems)
    for (int k = 0; k < 4; ++k) {
      const float t = rng.range(0.35f, 1.0f);
      const Vec3f c = stem_point(s, t);
      const Vec3f facing = Vec3f(0, 0, 1) + 0.6f * Vec3f(c.x(), c.y(), 0) / std::max(spread, 0.05f);
      add_leaf_card(b, rng, c - Vec3f(0, 0, 0.06f * height), facing, 0.7f, height * rng.range(0.16f, 0.24f));
    }
  return {b.finish(), Role::Shrub, cylinder_proxy(0.5f * reach + 0.05f, height)};
}

}  // namespace silva::assets
