#include <cmath>
#include <numbers>

#include "assets/generators.hpp"
#include "assets/strips.hpp"
#include "assets/understory_masks.hpp"

namespace silva::assets {

GeneratedAsset generate_leaf_litter(Rng& rng) {
  constexpr float kPi = std::numbers::pi_v<float>;
  const int cards = 3 + int(rng.below(5));
  const float spread = rng.range(0.05f, 0.12f);
  MeshBuilder b;
  b.begin_part(Role::Ground, Material::LeafLitter, litter_leaves_mask(), true);
  for (int i = 0; i < cards; ++i) {
    // A loose layer of fallen leaves: nearly flat cards, curled up a little at both ends.
    const float half = rng.range(0.05f, 0.1f), az = rng.range(0.0f, 2.0f * kPi);
    const Vec3f c = spread * std::sqrt(rng.uniform()) * horizontal(rng.range(0.0f, 2.0f * kPi)) +
                    Vec3f(0, 0, 0.004f + 0.006f * float(i));
    const Vec3f along = horizontal(az), curl(0, 0, half * rng.range(0.05f, 0.3f));
    const StripNode spine[] = {{c - half * along + curl, half}, {c, half}, {c + half * along + curl, half}};
    add_strip(b, spine, horizontal(az - 0.5f * kPi));
  }
  return {b.finish(), Role::Ground, CollisionProxy{}};
}

}  // namespace silva::assets
