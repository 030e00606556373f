#pragma once
/// @file A procedural asset's LOD meshes and their alpha masks as checksummed binary blobs (the
/// mesh cache's files): every array, part and mask bit for bit, so an unpacked mesh renders and
/// labels exactly as the one packed. Meshes name their masks by content hash, so a mask shared by
/// many variants is stored once.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/mesh.hpp"

namespace silva::assets {

/// A mask's content hash (size, cut-off, feature length, texels): its name in a pack.
uint64_t mask_hash(const AlphaMask& mask);

/// The mask as bytes.
std::string pack_mask(const AlphaMask& mask);

/// The mask `bytes` hold, or nothing when they are not a whole, intact mask pack.
std::optional<AlphaMask> unpack_mask(std::string_view bytes);

/// True when `lods` can be packed: no part carries an asset file's own colour (procedural meshes).
bool packable(std::span<const Mesh> lods);

/// Packed LOD meshes and the distinct masks their parts name.
struct PackedLods {
  std::string bytes;                                            ///< The meshes.
  std::vector<std::pair<uint64_t, const AlphaMask*>> masks;     ///< mask_hash and mask of each.
};

/// The LOD meshes as bytes; `lods` must be packable().
PackedLods pack_lods(std::span<const Mesh> lods);

/// The mask of a content hash, or null when it cannot be had.
using MaskLookup = std::function<std::shared_ptr<const AlphaMask>(uint64_t)>;

/// The meshes `bytes` hold, their masks from `lookup`, or nothing when they are not a whole,
/// intact pack (wrong magic or version, truncated, checksum mismatch, an index or part range out
/// of bounds, a mask the lookup lacks).
std::optional<std::vector<Mesh>> unpack_lods(std::string_view bytes, const MaskLookup& lookup);

}  // namespace silva::assets
