#include "systems/chunk_cache.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "systems/world_generator.hpp"

namespace silva::world {

std::vector<std::shared_ptr<const ChunkContent>> ChunkCache::require(const WorldContext& ctx,
                                                                     const std::vector<ChunkCoord>& coords) {
  std::vector<ChunkCoord> missing;
  for (ChunkCoord c : coords)
    if (!map_.count(c)) missing.push_back(c);
  std::sort(missing.begin(), missing.end());
  missing.erase(std::unique(missing.begin(), missing.end()), missing.end());
  std::vector<std::shared_ptr<const ChunkContent>> fresh(missing.size());
  tbb::parallel_for(size_t(0), missing.size(), [&](size_t k) {
    fresh[k] = std::make_shared<const ChunkContent>(generate_chunk(ctx, missing[k]));
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
