#pragma once
/// @file Packed instance ids (CONTRACT.md): (i mod 256) << 24 | (j mod 256) << 16 | (index + 1).
#include <cstdint>

#include "core/types.hpp"

namespace silva {

/// Packs an object's chunk and its index within the chunk (0-based, < 65535) into its instance id.
inline uint32_t pack_instance_id(ChunkCoord c, uint32_t index_in_chunk) {
  return (uint32_t(uint8_t(c.i)) << 24) | (uint32_t(uint8_t(c.j)) << 16) | ((index_in_chunk + 1) & 0xffffu);
}

/// Largest number of objects one chunk may hold (the low 16 bits of an instance id, minus 0).
inline constexpr uint32_t kMaxObjectsPerChunk = 65535;

}  // namespace silva
