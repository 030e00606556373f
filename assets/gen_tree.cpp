#include <algorithm>
#include <cmath>

#include "assets/species.hpp"

namespace silva::assets {

GeneratedAsset grow_tree(const Species& sp, Rng& rng) {
  const float age = rng.uniform();
  const float mature = rng.range(sp.mature_min, sp.mature_max);
  const float height = age < 0.2f ? rng.range(1.0f, 3.0f) : age < 0.5f ? mature * rng.range(0.3f, 0.6f) : mature;
  const float scale = std::min(1.0f, height / (0.5f * (sp.mature_min + sp.mature_max)));
  SkeletonParams p = sp.skeleton;
  p.height = height * sp.trunk_share;
  p.base_radius = std::max(0.02f, p.height * sp.slenderness * rng.range(0.85f, 1.15f) * (height < 4 ? 1.3f : 1.0f));
  LevelParams& stem = p.levels[0];
  stem.children = std::max(3, int(std::lround(float(stem.children) * (0.3f + 0.7f * scale))));
  stem.start *= 0.4f + 0.6f * scale;  // young trees keep their low branches
  TreeLook look = sp.look;
  if (height < 4.0f && p.levels.size() > 3) p.levels.pop_back();  // saplings: no finest order
  look.cards.level = std::min(look.cards.level, int(p.levels.size()) - 1);
  const float card_scale = std::clamp(std::sqrt(scale), 0.25f, 1.0f);
  look.cards.half *= card_scale;
  look.cards.spacing *= card_scale;
  const Skeleton s = grow_skeleton(p, rng);
  MeshBuilder b;
  mesh_tree(b, s, look, rng);
  return {b.finish(), Role::TreeTrunk, trunk_proxy(s)};
}

GeneratedAsset generate_spruce(Rng& rng) { return grow_tree(norway_spruce(), rng); }
GeneratedAsset generate_pine(Rng& rng) { return grow_tree(scots_pine(), rng); }
GeneratedAsset generate_larch(Rng& rng) { return grow_tree(european_larch(), rng); }
GeneratedAsset generate_beech(Rng& rng) { return grow_tree(european_beech(), rng); }
GeneratedAsset generate_birch(Rng& rng) { return grow_tree(silver_birch(), rng); }
GeneratedAsset generate_oak(Rng& rng) { return grow_tree(common_oak(), rng); }

}  // namespace silva::assets
