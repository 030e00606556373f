#include "app/cli/cli.hpp"

/// Entry point: all work happens in run_cli so tests can call it in-process.
int main(int argc, char** argv) { return silva::app::run_cli(argc, argv); }
