#pragma once
/// @file A memory-bounded LRU cache of generated chunks. Chunk content never depends on history,
/// so the cache changes speed, never results. The capture schedule keeps it as an ECS resource
/// (its systems generate the misses); require() generates misses itself for library callers.
#include <cstddef>
#include <list>
#include <map>
#include <memory>
#include <vector>

#include "world/chunk_content.hpp"
#include "world/world_context.hpp"

namespace silva::world {

/// Anything that hands out drawable chunks by coordinates (generating those it lacks).
class ChunkSource {
 public:
  virtual ~ChunkSource() = default;
  /// The chunks of `coords`, in that order.
  virtual std::vector<std::shared_ptr<const ChunkContent>> require(const WorldContext& ctx,
                                                                   const std::vector<ChunkCoord>& coords) = 0;
};

/// Chunk `coord` as the renderer draws it: generated, plus its terrain's coarse level and bounds.
ChunkContent drawable_chunk(const WorldContext& ctx, ChunkCoord coord);

/// drawable_chunk of each of `coords` (distinct), in that order, generated together (generate_chunks).
std::vector<std::shared_ptr<ChunkContent>> drawable_chunks(const WorldContext& ctx, const std::vector<ChunkCoord>& coords);

/// LRU cache of chunk contents keyed by chunk coordinates, as the renderer draws them: each with
/// its terrain's coarse level and bounds (ChunkContent::terrain_lod, terrain_bounds).
class ChunkCache : public ChunkSource {
 public:
  /// Cache holding at most `capacity` chunks after each require() (more only while one
  /// require() needs more at once).
  explicit ChunkCache(size_t capacity) : capacity_(capacity) {}
  /// Makes every chunk in `coords` present (missing ones generated in parallel with TBB), marks
  /// them most recently used (in the given order), then evicts least recently used beyond capacity.
  /// Returns the contents in the order of `coords`.
  std::vector<std::shared_ptr<const ChunkContent>> require(const WorldContext& ctx,
                                                           const std::vector<ChunkCoord>& coords) override;
  /// The chunks of `coords` that are not present, sorted and unique.
  std::vector<ChunkCoord> missing(const std::vector<ChunkCoord>& coords) const;
  /// Adds generated chunks (absent ones; each counts as generated) as the most recently used.
  void insert(std::vector<std::shared_ptr<ChunkContent>> chunks);
  /// Removes the chunks of `coords` (all present) and returns their contents in that order,
  /// moved out when nothing else holds them.
  std::vector<ChunkContent> release(const std::vector<ChunkCoord>& coords);
  /// Marks every chunk of `coords` (all present) most recently used in the given order, evicts
  /// the least recently used beyond capacity (never one of `coords`) and returns their contents
  /// in the order of `coords`. Throws std::out_of_range for a chunk that is not present.
  std::vector<std::shared_ptr<const ChunkContent>> take(const std::vector<ChunkCoord>& coords);
  /// Content of a present chunk, or null (does not change recency).
  std::shared_ptr<const ChunkContent> find(ChunkCoord c) const;
  /// Removes every chunk for which `drop(coord)` is true.
  template <class Pred>
  void evict_if(Pred&& drop) {
    for (auto it = lru_.begin(); it != lru_.end();) {
      if (drop(*it)) {
        map_.erase(*it);
        it = lru_.erase(it);
      } else {
        ++it;
      }
    }
  }
  /// Chunks present.
  size_t size() const { return map_.size(); }
  /// Bound on size() after require().
  size_t capacity() const { return capacity_; }
  /// Chunks generated so far (misses).
  size_t generated() const { return generated_; }
  /// Present chunk coordinates, most recently used first.
  const std::list<ChunkCoord>& recency() const { return lru_; }

 private:
  struct Entry {
    std::shared_ptr<ChunkContent> content;
    std::list<ChunkCoord>::iterator position;
  };
  size_t capacity_;
  size_t generated_ = 0;
  std::list<ChunkCoord> lru_;  // front = most recently used
  std::map<ChunkCoord, Entry> map_;
};

}  // namespace silva::world
