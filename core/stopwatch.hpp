#pragma once
/// @file Wall-clock timing on the steady clock: the one helper every timed phase uses.
#include <chrono>

namespace silva {

/// The clock every timing in Silva reads.
using SteadyClock = std::chrono::steady_clock;

/// Seconds elapsed on the steady clock since `start`.
inline double seconds_since(SteadyClock::time_point start) {
  return std::chrono::duration<double>(SteadyClock::now() - start).count();
}

/// Measures wall time from its construction (or the last restart).
class Stopwatch {
 public:
  /// Seconds since construction or the last restart().
  double seconds() const { return seconds_since(start_); }
  /// Starts counting again from now.
  void restart() { start_ = SteadyClock::now(); }

 private:
  SteadyClock::time_point start_ = SteadyClock::now();
};

}  // namespace silva
