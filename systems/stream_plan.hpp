#pragma once
/// @file What the Stream phase changes in one frame: which chunk entities to spawn, promote
/// from halo to full, and despawn. A pure function of the needed sets and the live chunks.
#include <map>
#include <vector>

#include "core/camera.hpp"
#include "core/types.hpp"

namespace silva::world {

/// Structural changes of one Stream phase, each list in (i, j) order.
struct StreamPlan {
  std::vector<ChunkCoord> spawn_full;  ///< New chunks to generate, place and resolve.
  std::vector<ChunkCoord> spawn_halo;  ///< New halo chunks (neighbour candidates only).
  std::vector<ChunkCoord> promote;     ///< Live halo chunks that must become full.
  std::vector<ChunkCoord> despawn;     ///< Live chunks to remove (with their vegetation).
};

/// Chunks the cameras need now: within `radius` of a camera or in its view frustum, plus `pinned`;
/// sorted, unique.
std::vector<ChunkCoord> needed_chunks(const std::vector<Camera>& cameras, const std::vector<ChunkCoord>& pinned,
                                      double radius, double chunk_size);

/// Plans a frame: every `required` chunk becomes full, every chunk within `ring` of one that is
/// not required becomes (at least) a halo; a full chunk stays while it is in `keep` (required
/// plus hysteresis) or needed as a halo, a halo while it is needed. `live` maps each live chunk
/// to whether it is a halo. `required` and `keep` must be sorted and unique.
StreamPlan plan_stream(const std::vector<ChunkCoord>& required, const std::vector<ChunkCoord>& keep,
                       const std::map<ChunkCoord, bool>& live, int ring);

}  // namespace silva::world
