#pragma once
/// @file Procedural 64x64 foliage silhouettes for alpha-tested cards (binary alpha, cutoff 0.5).
/// Each mask is built once and shared, so every asset using it refers to the same object.
/// Texture space: u to the right, v down (row 0 at the top of the card).
#include <memory>

#include "core/mesh.hpp"

namespace silva::assets {

/// Side length of every procedural mask, in texels.
inline constexpr int kMaskSize = 64;

/// A conifer needle spray: a stem along v (base at v = 1) with needles angled towards the tip.
std::shared_ptr<const AlphaMask> needle_spray_mask();


/// Scots pine: a twig tip (base at v = 1) with a brush of long needles fanning towards v = 0.
std::shared_ptr<const AlphaMask> pine_tuft_mask();

/// Larch: a twig along v with short needle tufts on either side.
std::shared_ptr<const AlphaMask> larch_tuft_mask();

/// Beech: a twig along v with alternate broad oval leaves.
std::shared_ptr<const AlphaMask> beech_leaves_mask();

/// Silver birch: a thin twig along v with small, sparse pointed leaves.
std::shared_ptr<const AlphaMask> birch_leaves_mask();

/// Oak: a twig along v with lobed leaves.
std::shared_ptr<const AlphaMask> oak_leaves_mask();

/// Dead twigs: a bare stem along v with forking side twigs.
std::shared_ptr<const AlphaMask> bare_twig_mask();

}  // namespace silva::assets
