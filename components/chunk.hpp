#pragma once
/// @file Chunk entities: the identity of a chunk being generated, and the resources that say which
/// chunks the frame needs. Generated data are the world library's plain structs
/// (world/chunk_content.hpp), attached as further components.
#include <vector>

#include "core/types.hpp"

namespace silva {

/// Chunk entity identity: its coordinates and whether it is only a halo (neighbour
/// candidates for resolving the chunks next to it: no terrain, no objects of its own).
struct Chunk {
  ChunkCoord coord;   ///< Chunk (i, j).
  bool halo = false;  ///< True while the chunk only supplies neighbour candidates.
};

/// Resource: chunks streamed whatever the cameras see (a region `silva world` builds).
struct PinnedChunks {
  std::vector<ChunkCoord> coords;  ///< Sorted, unique.
  bool for_drawing = false;        ///< Give them the coarse terrain level views draw.
};

/// Resource: the chunks the active camera's view needs this frame (sorted, unique).
struct ViewChunks {
  std::vector<ChunkCoord> coords;  ///< Frustum chunks plus the shadow-caster disc: what the camera's scene holds.
  /// Those of every view of the frame's fan (world/view_fan.hpp), a superset of coords: what its shared sun
  /// passes draw. Empty for a frame alone at its position.
  std::vector<ChunkCoord> fan;
  /// What the frame streams: fan, or coords without one.
  const std::vector<ChunkCoord>& streamed() const { return fan.empty() ? coords : fan; }
};

}  // namespace silva
