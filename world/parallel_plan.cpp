#include "world/parallel_plan.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <exception>

namespace silva::world {

namespace {
/// Tasks per batch and thread: enough to keep threads busy, few enough that a batch's chunks stay small.
constexpr size_t kTasksPerThread = 4;
}  // namespace

std::vector<SharedChunks::Slot> SharedChunks::claim(const std::vector<ChunkCoord>& coords,
                                                    const std::shared_ptr<Batch>& fresh) {
  const std::lock_guard lock(mutex_);
  std::vector<Slot> out;
  out.reserve(coords.size());
  for (ChunkCoord c : coords) {
    const auto [it, added] = slots_.try_emplace(c);
    Slot& s = it->second;
    if (added) {
      // The cache never hands out a chunk made const: its contents are made mutable and shared read-only.
      if (std::shared_ptr<const ChunkContent> cached = cache_->find(c)) {
        s.cached = std::const_pointer_cast<ChunkContent>(cached);
      } else {
        s.batch = fresh;
        s.index = fresh->coords.size();
        fresh->coords.push_back(c);
      }
    }
    out.push_back(s);
  }
  return out;
}

std::vector<std::shared_ptr<ChunkContent>> SharedChunks::get(const WorldContext& ctx,
                                                             const std::vector<ChunkCoord>& coords) {
  const std::vector<Slot> slots = claim(coords, std::make_shared<Batch>());
  std::vector<std::shared_ptr<ChunkContent>> out;
  out.reserve(slots.size());
  for (const Slot& s : slots) {
    if (s.batch) tbb::collaborative_call_once(s.batch->once, [&] { s.batch->contents = drawable_chunks(ctx, s.batch->coords); });
    out.push_back(s.content());
  }
  return out;
}

std::shared_ptr<ChunkContent> SharedChunks::asked(ChunkCoord c) const {
  const std::lock_guard lock(mutex_);
  return slots_.at(c).content();
}

std::vector<std::shared_ptr<const ChunkContent>> RecordedChunks::require(const WorldContext& ctx,
                                                                         const std::vector<ChunkCoord>& coords) {
  requests_.push_back(coords);
  std::vector<std::shared_ptr<ChunkContent>> got = shared_->get(ctx, coords);
  return {got.begin(), got.end()};
}

void RecordedChunks::replay(ChunkCache& cache) const {
  for (const std::vector<ChunkCoord>& coords : requests_) {
    std::vector<std::shared_ptr<ChunkContent>> fresh;
    for (ChunkCoord c : cache.missing(coords)) fresh.push_back(shared_->asked(c));
    cache.insert(std::move(fresh));
    cache.take(coords);
  }
}

void plan_in_parallel(ChunkCache& cache, size_t n,
                      const std::function<void(size_t, ChunkSource&)>& plan) {
  const size_t batch = kTasksPerThread * size_t(std::max(1, tbb::this_task_arena::max_concurrency()));
  for (size_t first = 0; first < n; first += batch) {
    const size_t count = std::min(batch, n - first);
    SharedChunks shared(cache);
    std::vector<RecordedChunks> tasks(count, RecordedChunks(shared));
    std::vector<std::exception_ptr> errors(count);
    tbb::parallel_for(size_t(0), count, [&](size_t k) {
      try {
        plan(first + k, tasks[k]);
      } catch (...) {
        errors[k] = std::current_exception();
      }
    });
    for (size_t k = 0; k < count; ++k) {
      tasks[k].replay(cache);
      if (errors[k]) std::rethrow_exception(errors[k]);
    }
  }
}

}  // namespace silva::world
