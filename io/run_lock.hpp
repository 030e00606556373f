#pragma once
/// @file The run-folder lock (CONTRACT.md "Output folder"): `generate`, `--resume` and `merge` hold
/// an exclusive flock on `<output.dir>/<seed>/` for the whole run, shards a shared one, so two
/// writers never mix their frames in one folder.
#include <filesystem>

namespace silva::io {

/// An flock held on a run folder until destruction (or process exit).
class RunLock {
 public:
  RunLock() = default;
  RunLock(RunLock&& other) noexcept;
  RunLock& operator=(RunLock&& other) noexcept;
  RunLock(const RunLock&) = delete;
  RunLock& operator=(const RunLock&) = delete;
  ~RunLock();

  /// True while the lock is held.
  bool held() const { return fd_ >= 0; }

 private:
  friend RunLock lock_run_folder(const std::filesystem::path& run_dir, bool exclusive);
  int fd_ = -1;
};

/// Creates `run_dir` if needed and locks it without waiting: exclusive for a run or a merge,
/// shared for a shard (shards of one run write side by side). InputError naming the holder's
/// PID when another process holds a conflicting lock; IoError when the folder cannot be made.
RunLock lock_run_folder(const std::filesystem::path& run_dir, bool exclusive);

}  // namespace silva::io
