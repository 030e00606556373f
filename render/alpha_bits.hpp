#pragma once
/// @file Alpha masks as one opacity bit per texel, the form the tile rasteriser gathers on SIMD lanes.
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "core/mesh.hpp"
#include "render/scene.hpp"

namespace silva::render {

/// A mask's opacity, one bit per texel: texel i (row-major) is opaque when bit i % 32 of
/// words[i / 32] is set. Sampled like AlphaMask (nearest texel, repeat wrap).
struct AlphaBits {
  int width = 0;                ///< Texels across.
  int height = 0;               ///< Texels down.
  std::vector<uint32_t> words;  ///< ceil(width * height / 32) words.
  /// The bits of `mask` (AlphaMask::opaque_texel for every texel).
  static AlphaBits of(const AlphaMask& mask);
  /// True when texel i (row-major) is opaque.
  bool opaque_texel(int i) const { return (words[size_t(i) / 32] >> (uint32_t(i) % 32)) & 1u; }
  /// Nearest-texel lookup with repeat wrap, as AlphaMask::opaque.
  bool opaque(float u, float v) const {
    return opaque_texel(AlphaMask::texel(v, height) * width + AlphaMask::texel(u, width));
  }
};

/// The AlphaBits of every mask a scene's meshes use, built once per mask and kept from pass to
/// pass while the scene still uses the mask (each entry holds its mask, so a cached address can
/// never be reused by another mask).
class AlphaBitsCache {
 public:
  /// Adds the masks of `scene` not seen yet and drops those it no longer uses.
  void update(const Scene& scene);
  /// The bits of a mask seen by the last update(), or null.
  const AlphaBits* find(const AlphaMask* mask) const;

 private:
  /// A cached mask and its bits.
  struct Entry {
    std::shared_ptr<const AlphaMask> mask;  ///< Keeps the mask (and so its address) alive.
    AlphaBits bits;                         ///< Its bits.
    uint64_t used = 0;                      ///< Last update() that saw it.
  };
  std::unordered_map<const AlphaMask*, Entry> entries_;  ///< By mask address.
  uint64_t updates_ = 0;                                 ///< Number of update() calls.
};

}  // namespace silva::render
