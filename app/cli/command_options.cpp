#include "app/cli/command_options.hpp"

#include <cmath>
#include <sstream>

#include <tbb/info.h>

#include "io/run_folder.hpp"

namespace silva::app {

void add_output_flags(CLI::App& cmd, OutputFlags& flags) {
  cmd.add_flag("--json", flags.json,
               "print one machine-readable JSON summary object on stdout (messages go to stderr)");
  cmd.add_flag("--quiet", flags.quiet, "print no progress or notes on stderr (errors still print)");
}

void add_config_options(CLI::App& cmd, ConfigSources& sources, bool with_seed) {
  cmd.add_option("--config", sources.file, "TOML config file (default: built-in defaults, "
                                           "documented in configs/default.toml)")
      ->type_name("FILE");
  cmd.add_option("--set", sources.overrides,
                 "override one config key, e.g. --set camera.fov_deg=75, --set "
                 "'output.types=[\"rgb\",\"depth\"]'; repeatable, applied in order after --config")
      ->type_name("KEY=VALUE")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  if (with_seed) {
    cmd.add_option_function<std::string>(
           "--seed", [&sources](const std::string& text) { sources.seed = text; },
           "world seed 0..9999999999 (overrides the config's seed; default: from the clock)")
        ->type_name("N");
  }
}

void add_threads_option(CLI::App& cmd, int& threads) {
  cmd.add_option("--threads", threads,
                 "worker threads (default: all cores); never changes an output byte")
      ->type_name("N")
      ->check(CLI::Range(1, 4096));
}

LoadedConfig load_run_config(const ConfigSources& sources, const Reporter& reporter, bool draw_seed) {
  LoadedConfig loaded = load_config(sources);
  if (draw_seed && !loaded.seed_given) {
    resolve_seed(loaded);
    reporter.note("silva: seed " + io::seed_folder_name(loaded.config.seed) + " (drawn from the clock)");
  }
  return loaded;
}

int resolved_threads(int requested) {
  return requested > 0 ? requested : tbb::info::default_concurrency();
}

ThreadLimit::ThreadLimit(int threads) {
  if (threads > 0) {
    control_ = std::make_unique<tbb::global_control>(
        tbb::global_control::max_allowed_parallelism, static_cast<size_t>(threads));
  }
}

CLI::Validator finite_range(double lo, double hi) {
  std::ostringstream range;
  range << "[" << lo << " - " << hi << "]";
  return CLI::Validator(
      [lo, hi, bounds = range.str()](std::string& text) -> std::string {
        double v = 0;
        if (!CLI::detail::lexical_cast(text, v) || !std::isfinite(v) || v < lo || v > hi)
          return "Value " + text + " not a finite number in " + bounds;
        return {};
      },
      "FLOAT in " + range.str());
}

}  // namespace silva::app
