#pragma once
/// @file Options several subcommands share: --json/--quiet, --config/--set/--seed, --threads.
#include <memory>
#include <optional>

#include <CLI/CLI.hpp>
#include <tbb/global_control.h>

#include "pipeline/console/reporter.hpp"
#include "pipeline/config/config_loader.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

/// Adds --json and --quiet to `cmd`.
void add_output_flags(CLI::App& cmd, OutputFlags& flags);

/// Adds --config F and --set key=value... to `cmd`, and --seed N when `with_seed`.
void add_config_options(CLI::App& cmd, ConfigSources& sources, bool with_seed);

/// Adds --threads N (≥ 1; 0, the default, means all cores) to `cmd`.
void add_threads_option(CLI::App& cmd, int& threads);

/// Loads and checks the config of a run; when `draw_seed` and no seed was given, draws one from
/// the clock and notes it on stderr. Throws InputError.
LoadedConfig load_run_config(const ConfigSources& sources, const Reporter& reporter, bool draw_seed);

/// The thread count a run uses: `requested`, or all cores when 0.
int resolved_threads(int requested);

/// A CLI check for a real-valued option: a finite number in [lo, hi] (CLI::Range lets nan through).
CLI::Validator finite_range(double lo, double hi);

/// Limits TBB to `threads` worker threads (0 = all cores) while it lives.
class ThreadLimit {
 public:
  /// Installs the limit.
  explicit ThreadLimit(int threads);

 private:
  std::unique_ptr<tbb::global_control> control_;
};

}  // namespace silva::app
