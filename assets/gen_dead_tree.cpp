#include <cmath>

#include "assets/alpha_masks.hpp"
#include "assets/dead_wood.hpp"
#include "assets/generators.hpp"
#include "assets/tree_mesh.hpp"

namespace silva::assets {

namespace {

/// Bare dead twigs as cards on the finest branches.
TreeLook dead_look(bool twigs) {
  TreeLook look{Material::BarkDead, Role::DeadTree, twigs, {}};
  look.cards = {.mask = nullptr, .family = bare_twig_spray, .material = Material::BarkDead, .role = Role::DeadTree,
                .style = CardStyle::Spray, .half = 0.3f, .spacing = 0.4f, .start = 0.2f, .droop = 0.1f,
                .level = 2, .max_cards = 800};
  look.torn_ends = true;
  return look;
}

}  // namespace

GeneratedAsset generate_dead_tree(Rng& rng) {
  const float length = rng.range(8.0f, 20.0f);
  const float r0 = std::clamp(length / 80.0f * rng.range(0.85f, 1.2f), 0.1f, 0.35f);
  const bool snapped = rng.uniform() < 0.8f;
  const float top = snapped ? rng.range(0.35f, 0.8f) : 1.0f;
  const Skeleton s = dead_skeleton(length, r0, top, rng);
  MeshBuilder b;
  mesh_tree(b, s, dead_look(rng.uniform() < 0.7f), rng);
  if (snapped) {
    const auto& trunk = s.branches.front().nodes;
    const TubeNode tip = trunk.back();
    const Vec3f dir = (tip.p - trunk[trunk.size() - 2].p).normalized();
    b.begin_part(Role::DeadTree, Material::BarkDead);
    const Vec3f off = 0.4f * tip.r * random_direction(rng).cross(dir).normalized();
    const TubeNode splinter[] = {{tip.p - 0.05f * dir + off, 0.5f * tip.r},
                                 {tip.p + rng.range(0.3f, 0.9f) * dir + 1.5f * off, kMinTubeRadius}};
    if (splinter[0].r > kMinTubeRadius) add_tube(b, splinter, 4);
    b.begin_part(Role::DeadTree, Material::Wood);
    add_disc(b, tip.p, dir, tip.r, 8);
  }
  return {b.finish(), Role::DeadTree, trunk_proxy(s)};
}

}  // namespace silva::assets
