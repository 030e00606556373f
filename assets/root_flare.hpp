#pragma once
/// @file The foot of a trunk: it widens into the ground over its lowest half metre (the round flare
/// of the bark tube) and, around that, rises in buttress ridges where the main roots leave it.
#include "assets/mesh_builder.hpp"
#include "assets/tree_skeleton.hpp"
#include "core/material.hpp"

namespace silva::assets {

/// The trunk's radius at the ground over its skeleton's base radius (the round flare of its tube).
inline constexpr float kFlareFoot = 1.3f;

/// Fraction of the trunk's length over which its foot flares: 4 %, at most 0.5 m.
float flare_fraction(const Branch& trunk);

/// Height of the buttress ridges over the trunk radius at the ground, by bark: beech and oak
/// strongly buttressed, spruce, larch and snags moderately, pine and birch little.
float buttress_lobe(Material bark);

/// Adds the buttressed foot of `trunk` (the skeleton's level-0 branch): 4-7 ridges (as many as a
/// hash of the trunk's length and radius says, so the tree's other random draws stay as they are)
/// from 0.2 m below its base, fading out where the round flare ends. Tube uv as add_tube's with `v_height`.
void add_root_flare(MeshBuilder& b, const Branch& trunk, Material bark, float v_height);

}  // namespace silva::assets
