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

/// Bilberry sprigs: thin twigs with many small oval alternate leaves (64 x 64).
std::shared_ptr<const AlphaMask> bilberry_leaves_mask();

/// Hazel: three broad, round, toothed leaves with pointed tips from the card centre (64 x 64).
std::shared_ptr<const AlphaMask> hazel_leaves_mask();

/// Bramble: one compound leaf of five toothed ovate leaflets on a stalk from v = 1 (64 x 64).
std::shared_ptr<const AlphaMask> bramble_leaf_mask();

/// Leaf litter: a few scattered oval and lobed fallen leaves (64 x 64).
std::shared_ptr<const AlphaMask> litter_leaves_mask();

}  // namespace silva::assets
