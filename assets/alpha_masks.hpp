#pragma once
/// @file The procedural 64x64 bare-twig silhouette of winter and dead crowns (binary alpha, cutoff
/// 0.5), built once and shared. Leafy crowns use foliage_sprays.hpp.
/// Texture space: u to the right, v down (row 0 at the top of the card).
#include <memory>

#include "core/mesh.hpp"

namespace silva::assets {

/// Side length of every procedural mask, in texels.
inline constexpr int kMaskSize = 64;

/// Dead twigs: a bare stem along v with forking side twigs.
std::shared_ptr<const AlphaMask> bare_twig_mask();

}  // namespace silva::assets
