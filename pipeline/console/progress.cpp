#include "pipeline/console/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace silva::pipeline {

Progress::Progress(const Reporter& reporter, int total, std::string what)
    : reporter_(reporter),
      total_(total),
      what_(std::move(what)),
      tty_(isatty(STDERR_FILENO) != 0),
      every_(std::max(1, total / 20)),
      start_(std::chrono::steady_clock::now()),
      last_line_(start_) {}

void Progress::update(int done) {
  if (reporter_.flags().quiet) return;
  const auto now = std::chrono::steady_clock::now();
  const bool due = done % every_ == 0 || done == total_ || now - last_line_ >= kLineInterval;
  if (!tty_ && !due) return;
  last_line_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = elapsed > 0 ? done / elapsed : 0.0;
  const double eta = rate > 0 ? (total_ - done) / rate : 0.0;
  if (tty_) {
    constexpr int kWidth = 30;
    const int filled = total_ > 0 ? done * kWidth / total_ : kWidth;
    std::fprintf(stderr, "\r[%s%s] %d/%d %s  %.1f %s/s  ETA %.0f s ", std::string(size_t(filled), '#').c_str(),
                 std::string(size_t(kWidth - filled), '.').c_str(), done, total_, what_.c_str(), rate, what_.c_str(),
                 eta);
    std::fflush(stderr);
  } else {
    std::fprintf(stderr, "silva: %d/%d %s, %.1f %s/s, ETA %.0f s\n", done, total_, what_.c_str(), rate,
                 what_.c_str(), eta);
  }
}

void Progress::finish() {
  if (tty_ && !reporter_.flags().quiet) std::fprintf(stderr, "\n");
}

}  // namespace silva::pipeline
