#pragma once
/// @file Pre-resolve placement candidates of a chunk (what the Place phase produces).
#include <cstdint>
#include <vector>

#include "core/asset_kind.hpp"
#include "core/types.hpp"

namespace silva::world {

/// One object proposed by placement, before overlap resolution.
struct Candidate {
  uint32_t asset = 0;            ///< Asset index in the library.
  AssetKind kind = AssetKind::Rock;  ///< Its kind.
  Vec3f position = Vec3f::Zero();  ///< Ground contact point (z on the terrain function).
  float yaw = 0;                 ///< Radians.
  float scale = 1;               ///< Uniform scale.
  float footprint = 0;           ///< Scaled footprint radius (metres).
  uint32_t point = 0;            ///< Grid point index within the chunk (row-major, x fastest).
  uint16_t sub = 0;              ///< Index among the objects of one point (ground vegetation).
  uint8_t rank = 0;              ///< Resolve rank of the kind (lower wins).
  uint64_t chunk_key = 0;        ///< ChunkCoord::key() of the owning chunk.
  uint64_t priority = 0;         ///< Hash tie-breaker within a rank (higher wins).
};

/// Candidates of one chunk, split into solids (with proxies) and ground vegetation.
struct ChunkCandidates {
  std::vector<Candidate> solids;  ///< Trees, dead trees, stumps, shrubs, rocks, logs.
  std::vector<Candidate> ground;  ///< Grass and ferns (empty unless requested).
  uint32_t trail_rejected = 0;    ///< Objects not placed because they met the trail corridor.
};

}  // namespace silva::world
