#pragma once
/// @file The silva command line: parses arguments, dispatches subcommands, returns the exit code.

namespace silva::app {

/// Runs the silva CLI with the given arguments; returns the process exit code (CONTRACT.md).
int run_cli(int argc, char** argv);

}  // namespace silva::app
