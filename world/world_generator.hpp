#pragma once
/// @file The chunk generation façade: terrain (trail included) + placement + resolve of one chunk.
#include "world/chunk_content.hpp"
#include "world/placement.hpp"
#include "world/resolve.hpp"
#include "world/world_context.hpp"

namespace silva::world {

/// Generates chunk `coord` completely (generate_chunks of that one chunk).
ChunkContent generate_chunk(const WorldContext& ctx, ChunkCoord coord);

/// Generates each of `coords` (distinct) completely, in parallel, in that order: the candidates of every chunk
/// within the neighbour ring of one of them are placed once for the whole batch. Each chunk equals
/// generate_chunk of it alone.
std::vector<ChunkContent> generate_chunks(const WorldContext& ctx, const std::vector<ChunkCoord>& coords);

/// Generates chunk `coord` with candidates looked up (e.g. precomputed for a whole region);
/// `own` must be place_candidates(ctx, coord, true). Same result as generate_chunk.
ChunkContent generate_chunk(const WorldContext& ctx, ChunkCoord coord, const ChunkCandidates& own,
                            const CandidateLookup& neighbours);

/// Sets `chunk`'s terrain mesh, the trail painted into it (the Generate phase's work), and its stats.
void add_terrain(const WorldContext& ctx, ChunkContent& chunk);

/// Sets `chunk`'s final objects, ids assigned, and their counters (the Resolve phase's work);
/// `own` must be place_candidates(ctx, chunk.coord, true).
void add_objects(const WorldContext& ctx, const ChunkCandidates& own, const CandidateLookup& neighbours,
                 ChunkContent& chunk);

/// Adds the coarse terrain level and the terrain bounds the renderer needs (made once per chunk
/// that is drawn, not in every world generation; timed into stats.generate_s).
void add_terrain_level(ChunkContent& chunk);

/// Assigns packed instance ids to the things (roles with instances) in list order; stuff gets 0.
/// Throws InputError when a chunk holds more than kMaxObjectsPerChunk things.
void assign_instance_ids(ChunkCoord coord, std::vector<Vegetation>& objects);

}  // namespace silva::world
