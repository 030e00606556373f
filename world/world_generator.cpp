#include "world/world_generator.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/instance_id.hpp"
#include "core/stopwatch.hpp"
#include "world/chunk_regions.hpp"
#include "world/terrain_lod.hpp"

namespace silva::world {

void assign_instance_ids(ChunkCoord coord, std::vector<Vegetation>& objects) {
  uint32_t index = 0;
  for (Vegetation& v : objects) {
    if (!role_has_instances(v.role)) continue;
    if (index >= kMaxObjectsPerChunk)
      throw InputError("chunk (" + std::to_string(coord.i) + ", " + std::to_string(coord.j) + ") holds more than " +
                       std::to_string(kMaxObjectsPerChunk) + " objects: lower vegetation.density");
    v.instance_id = pack_instance_id(coord, index++);
  }
}

void add_terrain(const WorldContext& ctx, ChunkContent& chunk) {
  const Stopwatch clock;
  chunk.terrain = build_terrain_mesh(ctx.terrain, ctx.chunk_size(), chunk.coord);
  chunk.stats.triangles = chunk.terrain.triangle_count();
  chunk.stats.generate_s = clock.seconds();
}

void add_objects(const WorldContext& ctx, const ChunkCandidates& own, const CandidateLookup& neighbours,
                 ChunkContent& chunk) {
  const Stopwatch clock;
  ResolveStats rs;
  chunk.objects = resolve_chunk(ctx, chunk.coord, own, neighbours, rs);
  assign_instance_ids(chunk.coord, chunk.objects);
  ChunkStats& st = chunk.stats;
  st.objects_by_role = {};
  for (const Vegetation& v : chunk.objects) ++st.objects_by_role[size_t(v.role)];
  st.candidates = uint32_t(own.solids.size() + own.ground.size());
  st.trail_rejected = own.trail_rejected;
  st.adjusted = rs.adjusted;
  st.dropped = rs.dropped;
  st.ground_dropped = rs.ground_dropped;
  st.broad_queries = rs.broad_queries;
  st.narrow_queries = rs.narrow_queries;
  st.resolve_s = clock.seconds();
}

void add_terrain_level(ChunkContent& chunk) {
  const Stopwatch clock;
  chunk.terrain_lod = build_terrain_lod(chunk.terrain);
  chunk.terrain_bounds = chunk.terrain.bounds();
  chunk.stats.generate_s += clock.seconds();
}

ChunkContent generate_chunk(const WorldContext& ctx, ChunkCoord coord, const ChunkCandidates& own,
                            const CandidateLookup& neighbours) {
  ChunkContent chunk;
  chunk.coord = coord;
  add_terrain(ctx, chunk);
  add_objects(ctx, own, neighbours, chunk);
  return chunk;
}

ChunkContent generate_chunk(const WorldContext& ctx, ChunkCoord coord) {
  return std::move(generate_chunks(ctx, {coord}).front());
}

std::vector<ChunkContent> generate_chunks(const WorldContext& ctx, const std::vector<ChunkCoord>& coords) {
  const std::vector<ChunkCoord> around = ring_neighbours(coords, ctx.neighbour_ring);
  std::vector<ChunkCandidates> around_candidates(around.size());
  tbb::parallel_for(size_t(0), around.size(),
                    [&](size_t k) { around_candidates[k] = place_candidates(ctx, around[k], false); });
  const CandidateLookup lookup = [&](ChunkCoord c) -> const ChunkCandidates& {
    return around_candidates[size_t(std::lower_bound(around.begin(), around.end(), c) - around.begin())];
  };
  std::vector<ChunkContent> out(coords.size());
  tbb::parallel_for(size_t(0), coords.size(), [&](size_t k) {
    const Stopwatch clock;
    const ChunkCandidates own = place_candidates(ctx, coords[k], true);
    const double place_s = clock.seconds();
    out[k] = generate_chunk(ctx, coords[k], own, lookup);
    out[k].stats.place_s = place_s;
  });
  return out;
}

}  // namespace silva::world
