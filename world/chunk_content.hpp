#pragma once
/// @file A chunk's generated content, the one chunk description (filled step by step: terrain,
/// then objects; the coarse terrain level once it is drawn), and its placement candidates:
/// plain data, a pure function of (seed, config, coordinates).
#include <array>
#include <cstdint>
#include <vector>

#include "core/aabb.hpp"
#include "core/mesh.hpp"
#include "core/ontology.hpp"
#include "core/types.hpp"
#include "world/candidate.hpp"

namespace silva {

/// How an object came to stand where it is (thesis Fig 4.5: correct / adjusted placement).
enum class Placement : uint8_t { Correct = 0, Adjusted = 1 };

/// One placed object: an asset variant at a world position, turned by yaw, uniformly scaled.
/// Object-to-world: p_world = position + Rz(yaw) * (scale * p_object).
struct Vegetation {
  uint32_t asset = 0;          ///< Index into the asset library.
  Role role = Role::Obstacle;  ///< Class of the object node (the asset's role).
  Placement placement = Placement::Correct;  ///< Correct or adjusted by overlap resolution.
  Vec3f position = Vec3f::Zero();  ///< Ground contact point (world, metres, on the terrain).
  float yaw = 0;               ///< Rotation about +Z, radians.
  float scale = 1;             ///< Uniform scale.
  uint32_t instance_id = 0;    ///< Packed instance id (0 for ground vegetation: stuff).
};

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
  uint64_t triangles = 0;        ///< Terrain triangles (the trail is part of the terrain).
  double generate_s = 0;         ///< Terrain mesh time (not part of the content hash).
  double place_s = 0;            ///< Placement time of its own candidates (its neighbours' are shared).
  double resolve_s = 0;          ///< Resolve time.
};

/// Everything generated for one chunk: a pure function of (seed, config, coordinates).
struct ChunkContent {
  ChunkCoord coord;                 ///< Chunk (i, j).
  Mesh terrain;                     ///< Terrain mesh in world coordinates (role Ground).
  Mesh terrain_lod;                 ///< Coarse terrain level for drawing: built when the chunk is first drawn, empty otherwise.
  AABB terrain_bounds;              ///< Bounds of terrain (terrain_lod uses its vertices): set with terrain_lod, else empty.
  std::vector<Vegetation> objects;  ///< Final objects in (grid point, sub) order.
  ChunkStats stats;                 ///< Counters and timings.
};

/// The Place step's output: a chunk's pre-resolve candidates.
struct ChunkPlacement {
  world::ChunkCandidates candidates;  ///< Solids, and ground vegetation for full chunks.
  double place_s = 0;                 ///< Time spent placing.
};

}  // namespace silva
