#pragma once
/// @file Turns a branching skeleton into a mesh: tapered bark tubes for branches at least
/// kMinTubeRadius thick, and alpha-masked foliage (or bare-twig) cards on the twigs.
#include <memory>

#include "assets/foliage_sprays.hpp"
#include "assets/generators.hpp"
#include "assets/tree_skeleton.hpp"
#include "core/rng.hpp"

namespace silva::assets {

/// Thinner branch parts than this radius (m) are drawn by cards, never as tubes (thin tubes alias).
inline constexpr float kMinTubeRadius = 0.015f;

/// Most triangles of one tree's full-detail mesh: cards are thinned to stay within it.
inline constexpr int kTreeTriangleBudget = 3000;

/// How cards sit on a twig.
enum class CardStyle : uint8_t {
  Spray,    ///< Card base on the twig, pointing along it (needle sprays, leafy shoots).
  Cluster,  ///< Card centred on the twig, facing outwards and up (leaf clusters).
};

/// Foliage (or bare twig) cards of one tree.
struct FoliageParams {
  std::shared_ptr<const AlphaMask> mask;  ///< Card silhouette (when `family` is unset).
  MaskFamily family = nullptr;            ///< Silhouettes per card size (botanical leaf size), or none.
  Material material = Material::Leaves;   ///< Card material.
  Role role = Role::TreeCanopy;           ///< Card role.
  CardStyle style = CardStyle::Spray;     ///< Placement.
  float half = 0.2f;        ///< Half size of a card (m).
  float spacing = 0.2f;     ///< Distance between cards along a twig (m).
  float start = 0.0f;       ///< Fraction of a twig's length where its cards begin.
  float droop = 0.2f;       ///< Spray cards tilt below their twig by this slope.
  int level = 2;            ///< Branches of this order and above carry cards along [start, 1].
  int max_cards = 4500;     ///< Cap: spacing grows until the tree has at most this many cards.
};

/// Bark and foliage of one tree.
struct TreeLook {
  Material bark = Material::BarkBroadleaf;  ///< Tube material; tube uv.y = node z / the skeleton's top z.
  Role bark_role = Role::TreeTrunk;         ///< Tube role.
  bool foliage = true;                      ///< False: no cards at all.
  FoliageParams cards;                      ///< The cards.
  bool torn_ends = false;                   ///< Branch stubs end in splintered broken_wood caps (dead wood).
};

/// Adds the bark part (tubes, the trunk flared and buttressed at the ground: root_flare.hpp) and the card part of `s` to `b`;
/// cards whose centre would lie inside the trunk are left out, and the card spacing grows so that
/// tubes and cards together stay within kTreeTriangleBudget (the buttressed foot, at most 168
/// triangles, comes on top, so it leaves the crown as it was). With look.torn_ends, every branch
/// tube that ends thicker than kMinTubeRadius (a broken-off stub) gets a splintered end cap in a
/// broken_wood part, on top of the budget (5 triangles per tube side), drawn after the cards.
void mesh_tree(MeshBuilder& b, const Skeleton& s, const TreeLook& look, Rng& rng);

/// The tree's collision proxy: a vertical cylinder of the trunk radius at breast height
/// (1.3 m, or the base for lower trunks) and the height of the trunk's tube.
CollisionProxy trunk_proxy(const Skeleton& s);

/// True when `p` lies inside the trunk (branch 0) tube.
bool inside_trunk(const Skeleton& s, const Vec3f& p);

}  // namespace silva::assets
