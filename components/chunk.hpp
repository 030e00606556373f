#pragma once
/// @file A terrain chunk: its generated content and the components of a chunk entity
/// (Stream -> Generate -> Place -> Resolve, DESIGN.md "Phases").
#include <array>
#include <cstdint>
#include <vector>

#include "components/candidate.hpp"
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
  Mesh terrain_lod;                 ///< Coarse terrain level for drawing: built by ChunkCache, empty otherwise.
  AABB terrain_bounds;              ///< Bounds of terrain (terrain_lod uses its vertices): set by ChunkCache, else empty.
  Mesh trail;                       ///< Trail piece in world coordinates (empty if none crosses).
  std::vector<Vegetation> objects;  ///< Final objects in (grid point, sub) order.
  ChunkStats stats;                 ///< Counters and timings.
};

/// Chunk entity identity: its coordinates and whether it is only a halo (neighbour
/// candidates for resolving the chunks next to it: no terrain, no objects of its own).
struct Chunk {
  ChunkCoord coord;   ///< Chunk (i, j).
  bool halo = false;  ///< True while the chunk only supplies neighbour candidates.
};

/// Generate phase output: the chunk's terrain and trail meshes.
struct ChunkTerrain {
  Mesh terrain;          ///< Terrain mesh in world coordinates (role Ground).
  Mesh trail;            ///< Trail piece in world coordinates (empty if none crosses).
  double generate_s = 0; ///< Time spent building both meshes.
  bool ready = false;    ///< True once generated.
};

/// Place phase output: the chunk's pre-resolve candidates.
struct ChunkPlacement {
  world::ChunkCandidates candidates;  ///< Solids, and ground vegetation once with_ground.
  double place_s = 0;                 ///< Time spent placing.
  bool placed = false;                ///< True once placed.
  bool with_ground = false;           ///< True when the ground vegetation was placed too.
};

/// Resolve phase output: the chunk's final objects (also spawned as Vegetation entities).
struct ChunkObjects {
  std::vector<Vegetation> objects;  ///< Final objects in (grid point, sub) order, ids assigned.
  ChunkStats stats;                 ///< Counters and timings (place, generate, resolve).
  bool resolved = false;            ///< True once resolved.
  bool populated = false;           ///< True once its Vegetation entities are spawned.
};

}  // namespace silva
