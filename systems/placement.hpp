#pragma once
/// @file Pre-resolve placement of one chunk (thesis 4.1.2, Fig 4.1): per grid point the
/// counter-based RNG keyed by (seed, chunk, point) picks a class by density, a position inside
/// the admissible circle, scale, yaw and a mesh variant. Nothing is placed on the trail corridor.
/// A pure function of (context, chunk coordinates).
#include <cstdint>
#include <vector>

#include "assets/library.hpp"
#include "core/types.hpp"
#include "systems/world_context.hpp"

namespace silva::world {

/// Admissible circle radius as a fraction of grid_spacing (strictly below one half).
inline constexpr double kAdmissibleFraction = 0.45;

/// One object proposed by placement, before overlap resolution.
struct Candidate {
  uint32_t asset = 0;            ///< Asset index in the library.
  assets::AssetKind kind = assets::AssetKind::Rock;  ///< Its kind.
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

/// True when a takes precedence over b in overlap resolution: rank, then hash, then identity.
bool outranks(const Candidate& a, const Candidate& b);

/// Candidates of one chunk, split into solids (with proxies) and ground vegetation.
struct ChunkCandidates {
  std::vector<Candidate> solids;  ///< Trees, dead trees, stumps, shrubs, rocks, logs.
  std::vector<Candidate> ground;  ///< Grass and ferns (empty unless requested).
  uint32_t trail_rejected = 0;    ///< Objects not placed because they met the trail corridor.
};

/// Places the candidates of chunk `coord`; ground vegetation only when with_ground is true
/// (solids never depend on it: every draw is keyed by its own point and purpose).
ChunkCandidates place_candidates(const WorldContext& ctx, ChunkCoord coord, bool with_ground);

}  // namespace silva::world
