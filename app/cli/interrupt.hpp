#pragma once
/// @file Ctrl-C during a run: the first SIGINT asks for a clean stop (exit 130, resumable), a
/// second one ends the process at once.
#include <stdexcept>

namespace silva::app {

/// Thrown by a pipeline that stopped cleanly after an interrupt; the CLI exits with 130.
struct Interrupted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Installs the SIGINT/SIGTERM handler that sets the stop request.
void install_interrupt_handler();

/// True once SIGINT or SIGTERM arrived; pipelines poll it between frames.
bool interrupt_requested();

}  // namespace silva::app
