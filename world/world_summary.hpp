#pragma once
/// @file Totals and a content hash over built chunks (the default world of CONTRACT.md "World
/// geometry"), for `silva world --stats` and determinism checks.
#include <array>
#include <cstdint>
#include <vector>

#include "world/chunk_content.hpp"

namespace silva::world {

/// Sums over a built world.
struct WorldTotals {
  uint64_t chunks = 0;                                  ///< Chunks built.
  uint64_t triangles = 0;                               ///< Terrain triangles (the trail is part of the terrain).
  std::array<uint64_t, kRoleCount> objects_by_role{};   ///< Final objects per class (role).
  uint64_t objects = 0;                                 ///< All final objects.
  uint64_t distinct_assets = 0;                         ///< Different asset variants the objects use.
  uint64_t candidates = 0;                              ///< Placement proposals in the built chunks.
  uint64_t trail_rejected = 0;                          ///< Proposals rejected on the trail corridor.
  uint64_t adjusted = 0;                                ///< Solids moved (adjusted placement).
  uint64_t dropped = 0;                                 ///< Solids dropped (no placement).
  uint64_t ground_dropped = 0;                          ///< Grass/ferns removed by solids.
  uint64_t broad_queries = 0;                           ///< Broad-phase queries.
  uint64_t narrow_queries = 0;                          ///< Narrow-phase fcl::collide calls.
  double place_s = 0;      ///< Wall time of the Place phase (all candidates).
  double chunks_s = 0;     ///< Wall time of the Generate (terrain) and Resolve phases.
  double terrain_cpu_s = 0;  ///< Summed per-chunk terrain mesh time.
  double resolve_cpu_s = 0;  ///< Summed per-chunk resolve time.
  double total_s = 0;      ///< Wall time of the whole build.
};

/// A built set of chunks in (i, j) order.
struct BuiltWorld {
  std::vector<ChunkContent> chunks;  ///< Sorted by (i, j).
  WorldTotals totals;                ///< Sums.
  uint64_t hash = 0;                 ///< world_hash(chunks).
};

/// xxHash (XXH3-64) over the chunks' contents (meshes and objects, not timings), in the given order.
uint64_t world_hash(const std::vector<ChunkContent>& chunks);

/// xxHash of one chunk's content.
uint64_t chunk_hash(const ChunkContent& chunk);

/// Adds a chunk's stats to the totals (counts one more chunk).
void accumulate(WorldTotals& totals, const ChunkStats& stats);

/// A built world of `chunks`: sorted by (i, j), totals summed (timings left to the caller), hashed.
BuiltWorld summarise_world(std::vector<ChunkContent> chunks);

}  // namespace silva::world
