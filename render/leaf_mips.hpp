#pragma once
/// @file Mip levels of a foliage mask's leaf brightness: what a pixel covering many texels of the mask
/// sees is the mean brightness of the leaves in its footprint, not the one leaf at its centre.
#include <cstdint>
#include <vector>

#include "core/mesh.hpp"

namespace silva::render {

/// The leaf brightness (render/materials.hpp leaf_brightness) of an alpha mask averaged over blocks of
/// 2^k x 2^k texels, k = 1, 2, ... while both sides stay whole: each coarse texel holds the mean
/// brightness of the opaque texels of its block, written back as an alpha in 128 … 254 (0 where the block
/// has no opaque texel). Level 0 is the mask itself.
class LeafMips {
 public:
  /// The levels of `mask` (whose size InputError-checks AlphaBits::of already made).
  static LeafMips of(const AlphaMask& mask);

  /// Alpha at (u, v) (repeat wrap, nearest texel) of the level for a pixel `texels_across` texels of
  /// level 0 wide: level floor(log2(texels_across)), at most the coarsest; level 0 below 2 texels across.
  /// Where level 0's texel at (u, v) is opaque, every level's is too.
  uint8_t alpha(const AlphaMask& mask, float u, float v, float texels_across) const;

  /// Number of levels besides level 0.
  int coarse_levels() const { return int(levels_.size()); }

 private:
  /// One level above 0.
  struct Level {
    int width = 0, height = 0;   ///< Texels across and down.
    std::vector<uint8_t> alpha;  ///< Row-major alphas.
  };
  std::vector<Level> levels_;  ///< levels_[k - 1] is level k.
};

}  // namespace silva::render
