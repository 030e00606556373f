#pragma once
/// @file Tree foliage masks at botanical scale: a branch spray of leaves or needles of a species'
/// real size, drawn for the size of the card that carries it (a small card shows a twig, a large
/// one a branch with hundreds of leaves), with enough texels that a leaf is at least ~12 long.
#include <memory>
#include <span>

#include "assets/mask_strokes.hpp"
#include "core/mesh.hpp"

namespace silva::assets {

/// How a species' leaves or needles sit on its twigs.
struct SprayLeaf {
  /// Where along a twig leaves grow and how.
  enum class Arrangement : uint8_t {
    Alternate,  ///< One leaf per step, sides alternating (broadleaves).
    Brush,      ///< A needle on both sides at every step (spruce, pine shoots).
    Rosette,    ///< Short shoots with a fan of needles on alternating sides (larch).
    Bare,       ///< No leaves: the twigs alone (winter and dead crowns; length_m sets their spacing).
  };
  float length_m = 0.07f;        ///< Leaf or needle length, metres.
  float half_width = 0.28f;      ///< Half-width as a share of the length.
  float angle_deg = 60.0f;       ///< Angle between twig and leaf, towards the twig's tip.
  float spacing = 0.7f;          ///< Distance between leaf steps along a twig, as a share of the length.
  float from = 0.15f;            ///< Share of each twig's length (from its base) left bare.
  int lobes = 0;                 ///< Pairs of side lobes per leaf (oak).
  Stroke::Shape shape = Stroke::Shape::Round;  ///< Width profile of a leaf.
  Arrangement arrangement = Arrangement::Alternate;  ///< Placement along the twigs.
  float twig_gap = 2.6f;         ///< Distance between side twigs, in leaf lengths.
  float coverage = 0.25f;        ///< Opaque share of the card the gaps are scaled to reach.
};

/// Card sides (metres) the masks are drawn for: kSprayClassSide * 2^k, k < kSprayClasses.
inline constexpr float kSprayClassSide = 0.25f;
/// Number of card-size classes.
inline constexpr int kSprayClasses = 4;

/// The class whose side is nearest (in ratio) to a card side of `card_side_m` metres.
int spray_class(float card_side_m);

/// The spray of `leaf` for cards of side `card_side_m`: stem along v from the base (v = 1) to the
/// tip, side twigs (and their side twigs where long enough) carrying leaves of leaf.length_m;
/// square (cutoff 0.5; each leaf's texels carry its own alpha in 128..254, a brightness, twigs 255),
/// 256 to 1024 texels a side, covering about leaf.coverage. AlphaMask::feature_length holds the
/// leaf length in texture units. `seed` varies the jitter between species.
std::shared_ptr<const AlphaMask> draw_spray(const SprayLeaf& leaf, float card_side_m, uint64_t seed);

/// A mask for each card size: the one a tree's cards of side `card_side_m` carry.
using MaskFamily = std::shared_ptr<const AlphaMask> (*)(float card_side_m);

/// Norway spruce: shoots as bottlebrushes of 1.8 cm needles.
std::shared_ptr<const AlphaMask> spruce_spray(float card_side_m);
/// Scots pine: brushes of 5 cm needles on the shoot ends.
std::shared_ptr<const AlphaMask> pine_spray(float card_side_m);
/// European larch: rosettes of 3 cm needles on short shoots.
std::shared_ptr<const AlphaMask> larch_spray(float card_side_m);
/// European beech: flat sprays of 7.5 cm oval leaves.
std::shared_ptr<const AlphaMask> beech_spray(float card_side_m);
/// Silver birch: thin twigs with 5 cm pointed leaves.
std::shared_ptr<const AlphaMask> birch_spray(float card_side_m);
/// Common oak: 10 cm lobed leaves crowded towards the twig ends.
std::shared_ptr<const AlphaMask> oak_spray(float card_side_m);
/// Bare twigs (winter and dead crowns): the branching of a spray without its leaves.
std::shared_ptr<const AlphaMask> bare_twig_spray(float card_side_m);

/// A spray family: the mask for a card side (every class of the family drawn on its first call).
using SprayFamily = std::shared_ptr<const AlphaMask> (*)(float card_side_m);

/// Every tree spray family (the six species' and the bare twigs'), for drawing them all at once.
std::span<const SprayFamily> spray_families();

/// The bare-twig spray for the card size a deciduous tree spray (beech, birch, oak, larch) was drawn
/// for, or nullptr when `leafy` is none of them.
std::shared_ptr<const AlphaMask> bare_twigs_for(const AlphaMask* leafy);

}  // namespace silva::assets
