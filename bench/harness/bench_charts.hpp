#pragma once
/// @file Drawing the PNG charts of a results file with scripts/bench_charts.py (python3 + matplotlib).
#include <filesystem>
#include <string>

namespace silva::bench {

/// Outcome of a chart run.
struct ChartRun {
  bool drawn = false;  ///< True when the script ran and succeeded.
  std::string note;    ///< What happened, or the command to run later.
};

/// Runs `python3 scripts/bench_charts.py RESULTS.json` (charts next to the file) when python3 with
/// matplotlib and numpy is available; otherwise says how to draw them later.
ChartRun draw_charts(const std::filesystem::path& results_json);

/// Runs `command` through the shell; returns its exit status (-1 when it could not start).
int run_shell(const std::string& command);

/// `text` in single quotes for the shell.
std::string shell_quote(const std::string& text);

}  // namespace silva::bench
