#include "ecs/ordered_stage.hpp"

#include <tbb/task_group.h>

#include <algorithm>
#include <utility>

namespace silva::ecs {

/// One submitted job and the task group running its parallel part.
struct OrderedStage::Job {
  std::uint64_t seq = 0;
  std::function<void()> parallel;
  std::function<void()> in_order;
  tbb::task_group group;
  bool ready = false;     // parallel part done
  bool finished = false;  // in-order part done (or skipped)
};

OrderedStage::OrderedStage(std::size_t limit) : limit_(limit) {}

void OrderedStage::set_limit(std::size_t limit) {
  while (in_flight() > 0) wait_oldest();
  limit_ = limit;
}

OrderedStage::~OrderedStage() {
  try {
    finish();
  } catch (...) {  // NOLINT(bugprone-empty-catch): a destructor must not throw; finish() reports errors
  }
}

std::size_t OrderedStage::in_flight() const {
  const std::lock_guard lock(mutex_);
  return jobs_.size();
}

bool OrderedStage::failed() const {
  const std::lock_guard lock(mutex_);
  return error_ != nullptr;
}

void OrderedStage::submit(std::function<void()> parallel, std::function<void()> in_order) {
  while (in_flight() >= std::max<std::size_t>(1, limit_)) wait_oldest();
  auto job = std::make_shared<Job>();
  job->parallel = std::move(parallel);
  job->in_order = std::move(in_order);
  {
    const std::lock_guard lock(mutex_);
    job->seq = next_seq_++;
    jobs_.push_back(job);
  }
  Job& j = *job;
  j.group.run([this, &j] {
    try {
      j.parallel();
    } catch (...) {
      fail(j.seq, std::current_exception());
    }
    parallel_done(j);
  });
  if (limit_ == 0) wait_oldest();
}

void OrderedStage::fail(std::uint64_t seq, std::exception_ptr error) {
  const std::lock_guard lock(mutex_);
  if (seq < failed_seq_) {
    failed_seq_ = seq;
    error_ = std::move(error);
  }
}

void OrderedStage::parallel_done(Job& job) {
  {
    const std::lock_guard lock(mutex_);
    job.ready = true;
  }
  drain();
}

void OrderedStage::drain() {
  std::unique_lock lock(mutex_);
  if (draining_) return;  // the draining thread will find this job
  draining_ = true;
  for (;;) {
    const auto it = std::find_if(jobs_.begin(), jobs_.end(), [&](const auto& j) { return j->seq == next_in_order_; });
    if (it == jobs_.end() || !(*it)->ready) break;
    Job& job = **it;
    const bool skip = job.seq >= failed_seq_;
    lock.unlock();
    try {
      if (!skip) job.in_order();
    } catch (...) {
      fail(job.seq, std::current_exception());
    }
    // Drop the closures now, so what they hold (a frame's buffers) is free before the job is reaped.
    job.parallel = nullptr;
    job.in_order = nullptr;
    lock.lock();
    job.finished = true;
    ++next_in_order_;
  }
  draining_ = false;
  lock.unlock();
  written_.notify_all();
}

void OrderedStage::wait_oldest() {
  std::shared_ptr<Job> job;
  {
    const std::lock_guard lock(mutex_);
    if (jobs_.empty()) return;
    job = jobs_.front();
  }
  job->group.wait();  // runs queued work on this thread meanwhile
  std::unique_lock lock(mutex_);
  // Another thread may still be running this job's in-order part.
  written_.wait(lock, [&] { return job->finished; });
  jobs_.pop_front();
}

void OrderedStage::finish() {
  while (in_flight() > 0) wait_oldest();
  std::exception_ptr error;
  {
    const std::lock_guard lock(mutex_);
    error = std::exchange(error_, nullptr);
    failed_seq_ = UINT64_MAX;
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace silva::ecs
