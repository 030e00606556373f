#pragma once
/// @file Alpha masks as one opacity bit per texel: the compact form the rasteriser gathers on SIMD
/// lanes and the ray caster's hit filter reads (an eighth of the mask's bytes, so it stays in cache).
#include <cstdint>
#include <vector>

#include "core/mesh.hpp"

namespace silva {

/// A mask's opacity, one bit per texel: texel i (row-major) is opaque when bit i % 32 of
/// words[i / 32] is set. Sampled like AlphaMask (nearest texel, repeat wrap).
struct AlphaBits {
  int width = 0;                ///< Texels across.
  int height = 0;               ///< Texels down.
  std::vector<uint32_t> words;  ///< ceil(width * height / 32) words.
  /// The bits of `mask` (AlphaMask::opaque_texel for every texel); InputError when its size and bytes disagree.
  static AlphaBits of(const AlphaMask& mask);
  /// True when texel i (row-major) is opaque.
  bool opaque_texel(int i) const { return (words[size_t(i) / 32] >> (uint32_t(i) % 32)) & 1u; }
  /// Nearest-texel lookup with repeat wrap, as AlphaMask::opaque.
  bool opaque(float u, float v) const {
    return opaque_texel(AlphaMask::texel(v, height) * width + AlphaMask::texel(u, width));
  }
};

}  // namespace silva
