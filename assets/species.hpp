#pragma once
/// @file European tree species as growth parameters for the branching generator, and the
/// generator that grows one tree of a species in a drawn age class (sapling, pole, mature).
#include "assets/generators.hpp"
#include "assets/tree_mesh.hpp"
#include "assets/tree_skeleton.hpp"

namespace silva::assets {

/// One species: mature size, branching per level, bark and foliage.
struct Species {
  const char* name;            ///< Species name, e.g. "norway_spruce".
  float mature_min;            ///< Lowest mature height (m).
  float mature_max;            ///< Highest mature height (m).
  float trunk_share;           ///< Trunk length / tree height (broadleaf trunks end inside the crown).
  float slenderness;           ///< Trunk base radius / trunk length.
  SkeletonParams skeleton;     ///< Branching of a mature tree (height and radius set per tree).
  TreeLook look;               ///< Bark and foliage of a mature tree.
};

/// Norway spruce: narrow cone to the ground, drooping branches with hanging twigs, dark needles.
const Species& norway_spruce();
/// Scots pine: long bare trunk, high rounded crown of upturned branches, needle tufts, orange upper bark.
const Species& scots_pine();
/// European larch: open cone of level branches with hanging twigs, soft light-green tufts.
const Species& european_larch();
/// European beech: tall smooth grey trunk, dense broad domed crown.
const Species& european_beech();
/// Silver birch: white trunk, narrow airy crown with long drooping twigs, small light leaves.
const Species& silver_birch();
/// Pedunculate oak: short thick furrowed trunk, wide crooked crown of heavy limbs.
const Species& common_oak();

/// Grows one tree of `sp`: draws an age class (20 % saplings 1-3 m, 30 % poles at 30-60 % of the
/// mature height, 50 % mature), scales branching and foliage to it, meshes it.
GeneratedAsset grow_tree(const Species& sp, Rng& rng);

}  // namespace silva::assets
