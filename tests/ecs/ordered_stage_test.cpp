#include "ecs/ordered_stage.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

namespace silva::ecs {
namespace {

/// Submits `n` jobs whose parallel parts finish in reverse-ish order and records the in-order parts.
std::vector<int> run_jobs(int threads, int n, std::size_t limit, std::size_t* peak) {
  std::vector<int> order;
  std::atomic<std::size_t> busy{0};
  tbb::task_arena arena(threads);
  arena.execute([&] {
    OrderedStage stage(limit);
    for (int i = 0; i < n; ++i) {
      stage.submit(
          [i, n, &busy, peak] {
            const std::size_t now = ++busy;
            if (peak && now > *peak) *peak = now;
            std::this_thread::sleep_for(std::chrono::microseconds(200 * ((n - i) % 4)));
            --busy;
          },
          [i, &order] { order.push_back(i); });
      EXPECT_LE(stage.in_flight(), limit);
    }
    stage.finish();
  });
  return order;
}

TEST(OrderedStage, InOrderPartsRunInSubmissionOrderOnAnyThreadCount) {
  std::vector<int> expected(40);
  for (int i = 0; i < 40; ++i) expected[i] = i;
  for (int threads : {1, 2, 4}) EXPECT_EQ(run_jobs(threads, 40, 3, nullptr), expected) << threads << " threads";
}

TEST(OrderedStage, NeverHoldsMoreThanItsLimit) {
  std::size_t peak = 0;
  run_jobs(4, 30, 2, &peak);
  EXPECT_LE(peak, 2u);
}

TEST(OrderedStage, OverlapsTheSubmitterWithEarlierJobs) {
  // One job in flight may still run while the submitter goes on: seen in 1 of 20 tries.
  bool overlapped = false;
  tbb::task_arena arena(2);
  for (int attempt = 0; attempt < 20 && !overlapped; ++attempt) {
    arena.execute([&] {
      OrderedStage stage(3);
      std::atomic<bool> done{false};
      stage.submit([&] { std::this_thread::sleep_for(std::chrono::milliseconds(20)); }, [&] { done = true; });
      overlapped = !done;  // submit returned before the job finished
      stage.finish();
      EXPECT_TRUE(done);
    });
  }
  EXPECT_TRUE(overlapped);
}

TEST(OrderedStage, LimitZeroFinishesEachJobBeforeSubmitReturns) {
  tbb::task_arena arena(2);
  arena.execute([] {
    OrderedStage stage(0);
    for (int i = 0; i < 5; ++i) {
      bool done = false;
      stage.submit([] { std::this_thread::sleep_for(std::chrono::milliseconds(2)); }, [&done] { done = true; });
      EXPECT_TRUE(done) << i;
      EXPECT_EQ(stage.in_flight(), 0u);
    }
  });
}

TEST(OrderedStage, FinishRethrowsTheFirstErrorAndSkipsLaterInOrderParts) {
  std::vector<int> written;
  OrderedStage stage(2);
  stage.submit([] {}, [&] { written.push_back(0); });
  stage.submit([] { throw std::runtime_error("encode failed"); }, [&] { written.push_back(1); });
  stage.submit([] {}, [&] { written.push_back(2); });
  EXPECT_THROW(
      {
        try {
          stage.finish();
        } catch (const std::runtime_error& e) {
          EXPECT_STREQ(e.what(), "encode failed");
          throw;
        }
      },
      std::runtime_error);
  EXPECT_EQ(written, std::vector<int>{0});
  EXPECT_TRUE(stage.in_flight() == 0);
}

}  // namespace
}  // namespace silva::ecs
