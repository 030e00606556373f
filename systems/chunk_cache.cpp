#include "systems/chunk_cache.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>

#include "systems/terrain_lod.hpp"
#include "systems/world_generator.hpp"

namespace silva::world {

namespace {

/// Chunk `coord` as the renderer draws it: generated, plus its terrain's coarse level and bounds
/// (made here, once per chunk that is drawn, rather than in every world generation or every
/// frame; timed in generate_s).
ChunkContent drawable_chunk(const WorldContext& ctx, ChunkCoord coord) {
  ChunkContent c = generate_chunk(ctx, coord);
  const auto t0 = std::chrono::steady_clock::now();
  c.terrain_lod = build_terrain_lod(c.terrain);
  c.terrain_bounds = c.terrain.bounds();
  c.stats.generate_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return c;
}

}  // namespace

std::vector<std::shared_ptr<const ChunkContent>> ChunkCache::require(const WorldContext& ctx,
                                                                     const std::vector<ChunkCoord>& coords) {
  std::vector<ChunkCoord> missing;
  for (ChunkCoord c : coords)
    if (!map_.count(c)) missing.push_back(c);
  std::sort(missing.begin(), missing.end());
  missing.erase(std::unique(missing.begin(), missing.end()), missing.end());
  std::vector<std::shared_ptr<const ChunkContent>> fresh(missing.size());
  tbb::parallel_for(size_t(0), missing.size(), [&](size_t k) {
    fresh[k] = std::make_shared<const ChunkContent>(drawable_chunk(ctx, missing[k]));
  });
  generated_ += missing.size();
  for (size_t k = 0; k < missing.size(); ++k) {
    lru_.push_front(missing[k]);
    map_.emplace(missing[k], Entry{fresh[k], lru_.begin()});
  }
  std::vector<std::shared_ptr<const ChunkContent>> out;
  out.reserve(coords.size());
  for (ChunkCoord c : coords) {
    Entry& e = map_.at(c);
    lru_.splice(lru_.begin(), lru_, e.position);
    out.push_back(e.content);
  }
  // Evict beyond capacity, but never a chunk this call needs.
  const size_t keep = std::max(capacity_, coords.size());
  while (map_.size() > keep) {
    map_.erase(lru_.back());
    lru_.pop_back();
  }
  return out;
}

std::shared_ptr<const ChunkContent> ChunkCache::find(ChunkCoord c) const {
  const auto it = map_.find(c);
  return it == map_.end() ? nullptr : it->second.content;
}

}  // namespace silva::world
