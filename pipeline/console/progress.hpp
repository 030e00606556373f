#pragma once
/// @file Progress of a long run on stderr: a live bar with frames/s and ETA on a terminal, one
/// line every 5 % of the items (and at least every 30 s) otherwise; nothing with --quiet.
#include <chrono>
#include <string>

#include "pipeline/console/reporter.hpp"

namespace silva::pipeline {

/// Reports `done of total` items of a run named `what`.
class Progress {
 public:
  /// Starts the clock; `what` names the items ("frames").
  Progress(const Reporter& reporter, int total, std::string what);
  /// Reports that `done` items are complete.
  void update(int done);
  /// Ends the live bar's line (call once after the last update).
  void finish();

 private:
  const Reporter& reporter_;
  int total_;
  std::string what_;
  bool tty_;
  int every_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_line_;
  /// Longest time between two progress lines without a terminal.
  static constexpr std::chrono::seconds kLineInterval{30};
};

}  // namespace silva::pipeline
