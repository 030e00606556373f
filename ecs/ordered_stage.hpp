#pragma once
/// @file Work a system hands off beyond its frame: each job runs a parallel part (any thread, any
/// order) and then an in-order part (one job at a time, in submission order), with a bounded
/// number of jobs in flight. Lets a Write-phase system overlap frame N's output with frame N+1.
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>

namespace silva::ecs {

/// A bounded, ordered asynchronous stage on the caller's TBB arena.
class OrderedStage {
 public:
  /// A stage holding at most `limit` unfinished jobs; with 0, submit() runs each job at once on
  /// the calling thread (for a single-thread arena, where nothing could overlap).
  explicit OrderedStage(std::size_t limit);
  /// Waits for every job (errors are dropped here: call finish() to see them).
  ~OrderedStage();
  OrderedStage(const OrderedStage&) = delete;
  OrderedStage& operator=(const OrderedStage&) = delete;

  /// Queues a job; while `limit` jobs are unfinished, first waits for the oldest (helping with
  /// queued work meanwhile). Once a job has failed, its in-order part and every later one are
  /// skipped; earlier jobs still finish.
  void submit(std::function<void()> parallel, std::function<void()> in_order);
  /// Waits for every job; rethrows the exception of the earliest failed job.
  void finish();
  /// Jobs submitted and not yet finished.
  std::size_t in_flight() const;
  /// Changes the limit (see the constructor); waits for every job first.
  void set_limit(std::size_t limit);
  /// True once a part of some job has thrown (finish() rethrows it).
  bool failed() const;

 private:
  struct Job;
  void wait_oldest();
  void fail(std::uint64_t seq, std::exception_ptr error);
  void parallel_done(Job& job);
  void drain();

  std::size_t limit_;
  mutable std::mutex mutex_;
  std::condition_variable written_;
  std::deque<std::shared_ptr<Job>> jobs_;  // unfinished, oldest first
  std::uint64_t next_seq_ = 0;             // sequence number of the next submitted job
  std::uint64_t next_in_order_ = 0;        // sequence number whose in-order part runs next
  bool draining_ = false;                  // a thread is running in-order parts
  std::uint64_t failed_seq_ = UINT64_MAX;  // earliest failed job (UINT64_MAX: none)
  std::exception_ptr error_;               // its exception
};

}  // namespace silva::ecs
