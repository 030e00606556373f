#pragma once
/// @file The opacity bits (core/alpha_bits.hpp) and leaf mips (render/leaf_mips.hpp) of a scene's alpha
/// masks, kept from pass to pass.
#include <memory>
#include <unordered_map>

#include "core/alpha_bits.hpp"
#include "render/leaf_mips.hpp"
#include "render/scene.hpp"

namespace silva::render {

/// The AlphaBits and LeafMips of every mask a scene's meshes use, built once per mask and kept from
/// pass to pass while the scene still uses the mask (each entry holds its mask, so a cached address
/// can never be reused by another mask).
class MaskCache {
 public:
  /// Adds the masks of `scene` not seen yet and drops those it no longer uses.
  void update(const Scene& scene);
  /// The bits of a mask seen by the last update(), or null.
  const AlphaBits* find(const AlphaMask* mask) const;
  /// The leaf mips of a mask seen by the last update(), or null.
  const LeafMips* leaf_mips(const AlphaMask* mask) const;

 private:
  /// A cached mask, its bits and its mips.
  struct Entry {
    std::shared_ptr<const AlphaMask> mask;  ///< Keeps the mask (and so its address) alive.
    AlphaBits bits;                         ///< Its bits.
    LeafMips mips;                          ///< Its leaf brightness mips.
    uint64_t used = 0;                      ///< Last update() that saw it.
  };
  /// The entry of a mask seen by the last update(), or null.
  const Entry* entry(const AlphaMask* mask) const;
  std::unordered_map<const AlphaMask*, Entry> entries_;  ///< By mask address.
  uint64_t updates_ = 0;                                 ///< Number of update() calls.
};

}  // namespace silva::render
