#include "systems/stream_chunks.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include "components/chunk.hpp"
#include "components/phase.hpp"
#include "components/world_source.hpp"
#include "systems/prefetch_chunks.hpp"
#include "world/chunk_cache.hpp"
#include "world/chunk_content.hpp"
#include "world/chunk_regions.hpp"
#include "world/world_context.hpp"

namespace silva::systems {

namespace {

/// The chunks within `ring` of any of `full` (sorted) that are not in `full`, sorted.
std::vector<ChunkCoord> halo_of(const std::vector<ChunkCoord>& full, int ring) {
  std::vector<ChunkCoord> halo = world::ring_neighbours(full, ring);
  std::erase_if(halo, [&](ChunkCoord c) { return std::binary_search(full.begin(), full.end(), c); });
  return halo;
}

/// Stores the prefetched chunks when they are exactly the needed chunks the cache lacks (as store_chunks would:
/// sorted, with their terrain's coarse level), else spawns chunk entities for those.
void stream(ecs::SystemContext& sys) {
  const world::WorldContext& ctx = *sys.resource<const WorldSource>().ctx;
  std::vector<ChunkCoord> needed = sys.resource<const ViewChunks>().streamed();
  const auto& pinned = sys.resource<const PinnedChunks>().coords;
  needed.insert(needed.end(), pinned.begin(), pinned.end());
  world::ChunkCache& cache = sys.resource<world::ChunkCache>();
  const std::vector<ChunkCoord> full = cache.missing(needed);
  if (full.empty()) return;  // chunks being made stay for the frame they are for
  std::vector<std::shared_ptr<ChunkContent>> ready = sys.resource<PrefetchedChunks>().take(full);
  if (!ready.empty()) {
    cache.insert(std::move(ready));
    return;
  }
  ecs::CommandBuffer& cb = sys.commands();
  for (ChunkCoord c : full) {
    ChunkContent content;
    content.coord = c;
    cb.spawn(Chunk{c, false}, ChunkPlacement{}, std::move(content));
  }
  for (ChunkCoord c : halo_of(full, ctx.neighbour_ring)) cb.spawn(Chunk{c, true}, ChunkPlacement{});
}

}  // namespace

void install_stream_chunks(ecs::World& world) {
  if (!world.has_resource<PinnedChunks>()) world.set_resource(PinnedChunks{});
  if (!world.has_resource<PrefetchedChunks>()) world.set_resource(PrefetchedChunks{});
  world.system("stream_chunks")
      .phase(Phase::Stream)
      .after("aim_camera")
      .reads_resource<WorldSource, ViewChunks, PinnedChunks>()
      .writes_resource<world::ChunkCache, PrefetchedChunks>()
      .writes<Chunk>()
      .run(stream);
}

}  // namespace silva::systems
