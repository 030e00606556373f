#pragma once
/// @file Overlap resolution of one chunk (thesis Fig 4.5: correct / adjusted / no placement),
/// deterministic across chunk borders (DESIGN.md "Determinism"):
/// - a candidate stays where it is unless a higher-priority candidate of its chunk or of a
///   neighbour collides with it (priority: kind rank, then hash);
/// - a blocked candidate moves to the periphery of the highest-priority object it hits, to a
///   spot free of every neighbour candidate and of its own chunk's kept objects, and at least
///   2 * rmax inside its own chunk; with no such spot in kMoveTries it is dropped;
/// - ground vegetation may overlap itself but is dropped where it meets a solid footprint.
/// Broad phase: a uniform grid of footprint circles; narrow phase: fcl::collide on the proxies.
#include <cstdint>
#include <functional>
#include <vector>

#include "world/chunk_content.hpp"
#include "world/placement.hpp"
#include "world/world_context.hpp"

namespace silva::world {

/// Periphery spots tried before an object is dropped.
inline constexpr int kMoveTries = 8;
/// Gap left between a moved object's footprint and the one it hit (metres).
inline constexpr float kMoveGap = 0.05f;

/// Counters of one chunk's resolution.
struct ResolveStats {
  uint32_t adjusted = 0;        ///< Solids moved to a periphery spot.
  uint32_t dropped = 0;         ///< Solids with no free spot (no placement).
  uint32_t ground_dropped = 0;  ///< Grass/ferns removed because they met a solid.
  uint64_t broad_queries = 0;   ///< Grid (broad-phase) queries.
  uint64_t narrow_queries = 0;  ///< fcl::collide calls.
};

/// Pre-resolve candidates of a chunk (own or neighbour): a pure function of its coordinates.
using CandidateLookup = std::function<const ChunkCandidates&(ChunkCoord)>;

/// Resolves chunk `coord` given its own candidates (with ground vegetation) and a lookup of the
/// candidates of the chunks within ctx.neighbour_ring. Returns the final objects in (point, sub)
/// order, instance ids not yet assigned.
std::vector<Vegetation> resolve_chunk(const WorldContext& ctx, ChunkCoord coord, const ChunkCandidates& own,
                                      const CandidateLookup& neighbours, ResolveStats& stats);

}  // namespace silva::world
