#pragma once
/// @file Planning tasks run in parallel over chunks that each is generated once, leaving the capture's
/// chunk cache as running the tasks one after another would.
#include <tbb/collaborative_call_once.h>

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "world/chunk_cache.hpp"

namespace silva::world {

/// Chunks shared by planning tasks that run at once: each generated once however many tasks ask
/// for it; chunks already in the capture's cache are read from there.
class SharedChunks {
 public:
  /// Reads the chunks present in `cache`, which must not change while tasks ask.
  explicit SharedChunks(const ChunkCache& cache) : cache_(&cache) {}
  /// The chunks of `coords` in that order: those neither asked for before nor cached generated together
  /// (drawable_chunks), the ones another task is making waited for (or helped with).
  std::vector<std::shared_ptr<ChunkContent>> get(const WorldContext& ctx, const std::vector<ChunkCoord>& coords);
  /// Content of a chunk some task asked for; throws std::out_of_range for one no task did.
  std::shared_ptr<ChunkContent> asked(ChunkCoord c) const;

 private:
  /// Chunks one get() call generates: made once, by whichever task asks first (the others help or wait).
  struct Batch {
    tbb::collaborative_once_flag once;
    std::vector<ChunkCoord> coords;
    std::vector<std::shared_ptr<ChunkContent>> contents;
  };
  /// One chunk: read from the cache, or made as entry `index` of `batch`.
  struct Slot {
    std::shared_ptr<ChunkContent> cached;
    std::shared_ptr<Batch> batch;
    size_t index = 0;
    /// The content (its batch made).
    const std::shared_ptr<ChunkContent>& content() const { return batch ? batch->contents[index] : cached; }
  };
  /// The slots of `coords`, in that order; chunks neither cached nor in a slot yet join `fresh`.
  std::vector<Slot> claim(const std::vector<ChunkCoord>& coords, const std::shared_ptr<Batch>& fresh);

  const ChunkCache* cache_;
  mutable std::mutex mutex_;
  std::map<ChunkCoord, Slot> slots_;
};

/// One planning task's chunk source: hands out SharedChunks' chunks and records what it asked for, in order.
class RecordedChunks final : public ChunkSource {
 public:
  /// Asks `shared`, which must outlive this.
  explicit RecordedChunks(SharedChunks& shared) : shared_(&shared) {}
  std::vector<std::shared_ptr<const ChunkContent>> require(const WorldContext& ctx,
                                                           const std::vector<ChunkCoord>& coords) override;
  /// Makes on `cache` the requests this task made, in order, as ChunkCache::require makes them (the same
  /// misses counted, the same recency and evictions), taking the missing chunks from the shared ones.
  void replay(ChunkCache& cache) const;

 private:
  SharedChunks* shared_;
  std::vector<std::vector<ChunkCoord>> requests_;
};

/// Runs `plan(i, chunks)` for every i < n, in parallel batches. Each task gets its chunks from a RecordedChunks;
/// after each batch the tasks' requests are replayed on `cache` in task order, so the cache ends as running
/// the tasks in order on it would leave it. When tasks throw, the first in task order's exception is rethrown
/// (after replaying the tasks before it). `plan` must depend on chunk contents only, not on the cache's state.
void plan_in_parallel(ChunkCache& cache, size_t n,
                      const std::function<void(size_t, ChunkSource&)>& plan);

}  // namespace silva::world
