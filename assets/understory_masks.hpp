#pragma once
/// @file Alpha masks of the understory and forest floor: pinnate fern fronds, grass clumps,
/// shrub leaves and leaf litter. Each is built once and shared; u right, v down, base at v = 1.
#include <memory>

#include "core/mesh.hpp"

namespace silva::assets {

/// Width and height (texels) of the pinnate frond mask: a long strip, 1:4.
inline constexpr int kFrondMaskWidth = 64, kFrondMaskHeight = 256;

/// A pinnate fern frond along v: bare stipe at the base, then opposite pinnae (each with lobed
/// pinnules) angled towards the tip, lanceolate outline tapering to a point at v = 0.
std::shared_ptr<const AlphaMask> pinnate_frond_mask();

/// A dense tuft of thin curved grass blades of mixed height rising from v = 1 (64 x 128).
std::shared_ptr<const AlphaMask> grass_tuft_mask();

/// Grass blades with two or three flowering stalks carrying seed heads (64 x 128).
std::shared_ptr<const AlphaMask> grass_seed_mask();

/// Width and height (texels) of the grass sward mask, and the blades across it.
inline constexpr int kGrassSwardMaskWidth = 256, kGrassSwardMaskHeight = 128, kGrassSwardBlades = 52;
/// Range of a sward blade's half-width at its base, mask units (of the mask's width).
inline constexpr float kGrassSwardBladeHalfWidth[2] = {0.006f, 0.009f};

/// A sward: kGrassSwardBlades fine upright blades side by side rising from v = 1, 0.45-1 of the
/// mask high, each its own brightness (alpha 150-250).
std::shared_ptr<const AlphaMask> grass_sward_mask();

/// Bilberry sprigs: thin twigs with many small oval alternate leaves (64 x 64).
std::shared_ptr<const AlphaMask> bilberry_leaves_mask();

/// Hazel: three broad, round, toothed leaves with pointed tips from the card centre (64 x 64).
std::shared_ptr<const AlphaMask> hazel_leaves_mask();

/// Bramble: one compound leaf of five toothed ovate leaflets on a stalk from v = 1 (64 x 64).
std::shared_ptr<const AlphaMask> bramble_leaf_mask();

/// Texels per side of the wood sorrel leaf mask.
inline constexpr int kWoodSorrelMaskSize = 256;

/// Wood sorrel: one trifoliate leaf from the card centre, three broad obcordate leaflets (each two
/// round lobes with a notch at the tip) 120 degrees apart, each its own brightness (alpha 160-240).
std::shared_ptr<const AlphaMask> wood_sorrel_leaf_mask();

/// Texels per side of the woodruff whorl mask, and the leaves of one whorl.
inline constexpr int kWoodruffMaskSize = 256, kWoodruffWhorlLeaves = 8;

/// Woodruff: one whorl of kWoodruffWhorlLeaves narrow lanceolate leaves radiating from the card centre
/// (reaching 0.46 of the side), each its own brightness (alpha 130-200: a deeper green than wood sorrel).
std::shared_ptr<const AlphaMask> woodruff_whorl_mask();

/// Texels per side of the nettle leaf-pair mask.
inline constexpr int kNettleMaskSize = 256;

/// Stinging nettle: one opposite pair of ovate, coarsely toothed leaves with drawn-out tips from the card
/// centre (reaching 0.46 of the side), each its own brightness (alpha 128-175: a dark, dull green).
std::shared_ptr<const AlphaMask> nettle_pair_mask();

/// Texels per side of the wood anemone leaf-whorl and flower masks, and the tepals of its flower.
inline constexpr int kWoodAnemoneMaskSize = 256, kWoodAnemoneTepals = 6;

/// Wood anemone: one whorl of three stalked leaves 120 degrees apart from the card centre, each palmately cut into
/// three toothed segments (the whorl reaching 0.46 of the side), each leaf its own brightness (alpha 140-200).
std::shared_ptr<const AlphaMask> wood_anemone_whorl_mask();

/// Wood anemone flower seen from above: kWoodAnemoneTepals broad elliptic tepals round the card centre (reaching
/// 0.46 of the side), their bases a little darker, the centre (the yellow stamens) darker still.
std::shared_ptr<const AlphaMask> wood_anemone_flower_mask();

/// Width and height (texels) of the herb stalk mask.
inline constexpr int kHerbStalkMaskWidth = 32, kHerbStalkMaskHeight = 256;

/// A herb's leaf stalk: one line along v, a third of the card wide at the base (v = 1) tapering to a
/// quarter at the top, on a narrow card (a stalk drawn as a masked card keeps a card-only asset at one level).
std::shared_ptr<const AlphaMask> herb_stalk_mask();

/// Leaf litter: a few scattered oval and lobed fallen leaves (64 x 64).
std::shared_ptr<const AlphaMask> litter_leaves_mask();

}  // namespace silva::assets
