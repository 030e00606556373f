#include "world/chunk_cache.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "world/world_generator.hpp"

namespace silva::world {

ChunkContent drawable_chunk(const WorldContext& ctx, ChunkCoord coord) {
  ChunkContent c = generate_chunk(ctx, coord);
  add_terrain_level(c);
  return c;
}

std::vector<std::shared_ptr<ChunkContent>> drawable_chunks(const WorldContext& ctx, const std::vector<ChunkCoord>& coords) {
  std::vector<ChunkContent> made = generate_chunks(ctx, coords);
  std::vector<std::shared_ptr<ChunkContent>> out(made.size());
  tbb::parallel_for(size_t(0), made.size(), [&](size_t k) {
    add_terrain_level(made[k]);
    out[k] = std::make_shared<ChunkContent>(std::move(made[k]));
  });
  return out;
}

std::vector<std::shared_ptr<const ChunkContent>> ChunkCache::require(const WorldContext& ctx,
                                                                     const std::vector<ChunkCoord>& coords) {
  insert(drawable_chunks(ctx, missing(coords)));
  return take(coords);
}

std::vector<ChunkCoord> ChunkCache::missing(const std::vector<ChunkCoord>& coords) const {
  std::vector<ChunkCoord> out;
  for (ChunkCoord c : coords)
    if (!map_.count(c)) out.push_back(c);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

void ChunkCache::insert(std::vector<std::shared_ptr<ChunkContent>> chunks) {
  for (auto& chunk : chunks) {
    const ChunkCoord c = chunk->coord;
    if (map_.count(c)) continue;
    lru_.push_front(c);
    map_.emplace(c, Entry{std::move(chunk), lru_.begin()});
    ++generated_;
  }
}

std::vector<std::shared_ptr<const ChunkContent>> ChunkCache::take(const std::vector<ChunkCoord>& coords) {
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

std::vector<ChunkContent> ChunkCache::release(const std::vector<ChunkCoord>& coords) {
  std::vector<ChunkContent> out;
  out.reserve(coords.size());
  for (ChunkCoord c : coords) {
    const auto it = map_.find(c);
    std::shared_ptr<ChunkContent> content = std::move(it->second.content);
    lru_.erase(it->second.position);
    map_.erase(it);
    out.push_back(content.use_count() == 1 ? std::move(*content) : *content);
  }
  return out;
}

std::shared_ptr<const ChunkContent> ChunkCache::find(ChunkCoord c) const {
  const auto it = map_.find(c);
  return it == map_.end() ? nullptr : it->second.content;
}

}  // namespace silva::world
