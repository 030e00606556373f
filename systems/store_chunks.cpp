#include "systems/store_chunks.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

#include "components/camera.hpp"
#include "components/chunk.hpp"
#include "components/phase.hpp"
#include "world/chunk_cache.hpp"
#include "world/world_generator.hpp"

namespace silva::systems {

namespace {

/// Moves the finished chunks into the cache and despawns the chunk entities.
void store(ecs::SystemContext& sys) {
  std::vector<std::shared_ptr<ChunkContent>> done;
  sys.each<ChunkContent>([&](ChunkContent& chunk) { done.push_back(std::make_shared<ChunkContent>(std::move(chunk))); });
  ecs::CommandBuffer& cb = sys.commands();
  sys.each<const Chunk>([&](ecs::Entity e, const Chunk&) { cb.despawn(e); });
  if (done.empty()) return;
  std::sort(done.begin(), done.end(), [](const auto& a, const auto& b) { return a->coord < b->coord; });
  const bool drawn = !sys.resource<const CaptureQueue>().active.is_null() || sys.resource<const PinnedChunks>().for_drawing;
  if (drawn)
    tbb::parallel_for(size_t(0), done.size(), [&](size_t k) { world::add_terrain_level(*done[k]); });
  sys.resource<world::ChunkCache>().insert(std::move(done));
}

}  // namespace

void install_store_chunks(ecs::World& world) {
  world.system("store_chunks")
      .phase(Phase::Resolve)
      .after("resolve_overlaps")
      .reads_resource<CaptureQueue, PinnedChunks>()
      .writes_resource<world::ChunkCache>()
      .writes<Chunk, ChunkContent>()
      .run(store);
}

}  // namespace silva::systems
