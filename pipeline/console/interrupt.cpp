#include "pipeline/console/interrupt.hpp"

#include <unistd.h>

#include <csignal>

namespace silva::pipeline {

namespace {

volatile std::sig_atomic_t g_interrupted = 0;
volatile std::sig_atomic_t g_writing = 0;

extern "C" void on_interrupt(int signal) {
  if (!g_writing) {
    // Nothing is written yet (loading, checking, planning): stop at once, leaving no trace.
    static const char kLine[] = "silva: error: interrupted before anything was written\n";
    [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, kLine, sizeof kLine - 1);
    ::_exit(130);
  }
  g_interrupted = 1;
  std::signal(signal, SIG_DFL);  // a second signal ends the process
}

}  // namespace

void install_interrupt_handler() {
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
}

void begin_writing() { g_writing = 1; }

bool interrupt_requested() { return g_interrupted != 0; }

}  // namespace silva::pipeline
