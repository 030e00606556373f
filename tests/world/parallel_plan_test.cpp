#include "world/parallel_plan.hpp"

#include <gtest/gtest.h>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <stdexcept>
#include <string>

#include "tests/common/test_library.hpp"

namespace silva::world {
namespace {

/// The chunks task `i` asks for, in two requests that overlap the neighbouring tasks' chunks.
std::vector<std::vector<ChunkCoord>> task_requests(size_t i) {
  const int x = int(i % 5), y = int(i / 5);
  return {{{x, y}, {x + 1, y}}, {{x, y + 1}, {x, y}}};
}

/// Runs task `i`: its requests through `chunks`, checking each chunk handed out is the one asked for.
void run_task(const WorldContext& ctx, size_t i, ChunkSource& chunks) {
  for (const std::vector<ChunkCoord>& coords : task_requests(i)) {
    const auto got = chunks.require(ctx, coords);
    ASSERT_EQ(got.size(), coords.size());
    for (size_t k = 0; k < coords.size(); ++k) EXPECT_EQ(got[k]->coord, coords[k]);
  }
}

/// A cache of `capacity` holding two chunks from before the tasks.
ChunkCache warm_cache(const WorldContext& ctx, size_t capacity) {
  ChunkCache cache(capacity);
  cache.require(ctx, {{2, 1}, {9, 9}});
  return cache;
}

Config fast_config() {
  Config cfg = test::small_world_config(12, 1);
  cfg.vegetation.ground = false;  // planning does not depend on content; keep chunks cheap
  return cfg;
}

TEST(PlanInParallel, LeavesTheCacheAsRunningTheTasksInOrderDoes) {
  const WorldContext ctx = make_world_context(fast_config(), test::small_library());
  const size_t tasks = 23;
  ChunkCache serial = warm_cache(ctx, 6);
  for (size_t i = 0; i < tasks; ++i) run_task(ctx, i, serial);
  for (const int threads : {1, 3, 8}) {
    ChunkCache cache = warm_cache(ctx, 6);
    tbb::task_arena(threads).execute(
        [&] { plan_in_parallel(cache, tasks, [&](size_t i, ChunkSource& chunks) { run_task(ctx, i, chunks); }); });
    EXPECT_EQ(cache.recency(), serial.recency()) << threads << " threads";
    EXPECT_EQ(cache.generated(), serial.generated()) << threads << " threads";
  }
}

TEST(PlanInParallel, MakesEachChunkOnceForAllTasksThatAskAtOnce) {
  const WorldContext ctx = make_world_context(fast_config(), test::small_library());
  ChunkCache cache(64);
  SharedChunks shared(cache);
  std::vector<std::shared_ptr<ChunkContent>> got(16);
  tbb::task_arena(8).execute([&] {
    tbb::parallel_for(size_t(0), got.size(), [&](size_t k) { got[k] = shared.get(ctx, {{4, 4}, {4, 5}})[k % 2]; });
  });
  for (size_t k = 2; k < got.size(); ++k) EXPECT_EQ(got[k], got[k % 2]) << k;  // one object per chunk
  EXPECT_NE(got[0], got[1]);
  EXPECT_EQ(shared.asked({4, 5}), got[1]);
  EXPECT_THROW(shared.asked({0, 0}), std::out_of_range);
}

TEST(PlanInParallel, RethrowsTheFirstFailingTaskInTaskOrder) {
  const WorldContext ctx = make_world_context(fast_config(), test::small_library());
  const auto plan = [&](size_t i, ChunkSource& chunks) {
    run_task(ctx, i, chunks);
    if (i == 5 || i == 9) throw std::runtime_error("task " + std::to_string(i));
  };
  ChunkCache serial = warm_cache(ctx, 6);
  for (size_t i = 0; i <= 5; ++i) run_task(ctx, i, serial);
  ChunkCache cache = warm_cache(ctx, 6);
  try {
    tbb::task_arena(4).execute([&] { plan_in_parallel(cache, 12, plan); });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "task 5");
  }
  EXPECT_EQ(cache.recency(), serial.recency());  // the tasks before it, and its own requests, replayed
}

}  // namespace
}  // namespace silva::world
