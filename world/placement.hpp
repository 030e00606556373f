#pragma once
/// @file Pre-resolve placement of one chunk (thesis 4.1.2, Fig 4.1): per grid point the
/// counter-based RNG keyed by (seed, chunk, point) picks a class by density, a position inside
/// the admissible circle, scale, yaw and a mesh variant. Nothing is placed on the trail corridor.
/// A pure function of (context, chunk coordinates).
#include <cstdint>
#include <vector>

#include "assets/library.hpp"
#include "world/candidate.hpp"
#include "core/types.hpp"
#include "world/world_context.hpp"

namespace silva::world {

/// Admissible circle radius as a fraction of grid_spacing (strictly below one half).
inline constexpr double kAdmissibleFraction = 0.45;

/// True when a takes precedence over b in overlap resolution: rank, then hash, then identity.
bool outranks(const Candidate& a, const Candidate& b);

/// Places the candidates of chunk `coord`; ground vegetation only when with_ground is true
/// (solids never depend on it: every draw is keyed by its own point and purpose).
ChunkCandidates place_candidates(const WorldContext& ctx, ChunkCoord coord, bool with_ground);

}  // namespace silva::world
