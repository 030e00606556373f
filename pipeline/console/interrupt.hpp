#pragma once
/// @file Ctrl-C (SIGINT or SIGTERM) during a run: before anything is written it ends the process
/// at once (exit 130, one line); once writing began, the first one asks for a clean stop (exit
/// 130, resumable) and a second one ends the process at once.
#include <stdexcept>

namespace silva::pipeline {

/// Thrown by a pipeline that stopped cleanly after an interrupt; the CLI exits with 130.
struct Interrupted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Installs the SIGINT/SIGTERM handler that sets the stop request.
void install_interrupt_handler();

/// Switches the handler from stopping at once to asking the pipeline for a clean stop; call it
/// just before the first file is written.
void begin_writing();

/// True once SIGINT or SIGTERM arrived; pipelines poll it between frames.
bool interrupt_requested();

}  // namespace silva::pipeline
