// `silva bench`: the end-to-end benchmark harness.
#include <memory>

#include "app/command_options.hpp"
#include "app/commands.hpp"
#include "app/subcommands.hpp"

namespace silva::app {

Handler add_bench_command(CLI::App& root) {
  auto request = std::make_shared<BenchRequest>();
  auto output = std::make_shared<OutputFlags>();
  CLI::App* cmd = root.add_subcommand(
      "bench",
      "Run the end-to-end benchmarks that reproduce the thesis tables on this machine and write "
      "bench/results/*.json (fixed seeds; cold and warm runs; 1 and 2 threads).");
  cmd->add_flag("--quick", request->quick, "a short subset (minutes instead of ~20)");
  add_output_flags(*cmd, *output);
  cmd->footer("Examples:\n  silva bench --quick\n  silva bench --json > results.json");
  return [request, output] { return run_bench(*request, Reporter(*output)); };
}

}  // namespace silva::app
