#pragma once
/// @file A terrain chunk and its generated content (terrain mesh, trail piece, objects, stats).
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "components/vegetation.hpp"
#include "core/mesh.hpp"
#include "core/ontology.hpp"
#include "core/types.hpp"

namespace silva {

/// Work counters and timings of one chunk's generation.
struct ChunkStats {
  std::array<uint32_t, kRoleCount> objects_by_role{};  ///< Final objects per class (role).
  uint32_t candidates = 0;       ///< Objects proposed by placement (solid + ground).
  uint32_t trail_rejected = 0;   ///< Proposals rejected on the trail corridor.
  uint32_t adjusted = 0;         ///< Solids moved to a free periphery spot.
  uint32_t dropped = 0;          ///< Solids with no free spot (no placement).
  uint32_t ground_dropped = 0;   ///< Grass/ferns removed because they met a solid.
  uint64_t broad_queries = 0;    ///< Broad-phase (grid) queries.
  uint64_t narrow_queries = 0;   ///< Narrow-phase fcl::collide calls.
  uint64_t triangles = 0;        ///< Terrain + trail triangles.
  double generate_s = 0;         ///< Terrain + trail mesh time (not part of the content hash).
  double place_s = 0;            ///< Placement time, own and neighbour candidates.
  double resolve_s = 0;          ///< Resolve time.
};

/// Everything generated for one chunk: a pure function of (seed, config, coordinates).
struct ChunkContent {
  ChunkCoord coord;                 ///< Chunk (i, j).
  Mesh terrain;                     ///< Terrain mesh in world coordinates (role Ground).
  Mesh trail;                       ///< Trail piece in world coordinates (empty if none crosses).
  std::vector<Vegetation> objects;  ///< Final objects in (grid point, sub) order.
  ChunkStats stats;                 ///< Counters and timings.
};

/// Chunk entity component: its coordinates and (once generated) its immutable content.
struct Chunk {
  ChunkCoord coord;                              ///< Chunk (i, j).
  std::shared_ptr<const ChunkContent> content;   ///< Null until generated.
  uint64_t last_used_frame = 0;                  ///< Frame that last needed it (LRU).
};

}  // namespace silva
