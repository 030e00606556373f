#pragma once
/// @file Procedural 64x64 foliage silhouettes for alpha-tested cards (binary alpha, cutoff 0.5).
/// Each mask is built once and shared, so every asset using it refers to the same object.
/// Texture space: u to the right, v down (row 0 at the top of the card).
#include <memory>

#include "core/mesh.hpp"

namespace silva::assets {

/// Side length of every procedural mask, in texels.
inline constexpr int kMaskSize = 64;

/// A cluster of pointed broadleaf leaves around the card centre.
std::shared_ptr<const AlphaMask> leaf_cluster_mask();

/// A conifer needle spray: a stem along v (base at v = 1) with needles angled towards the tip.
std::shared_ptr<const AlphaMask> needle_spray_mask();


}  // namespace silva::assets
