// `silva bench`: the end-to-end benchmark harness.
#include <memory>

#include "app/cli/command_options.hpp"
#include "app/cli/subcommands.hpp"
#include "app/commands/bench/bench_command.hpp"

namespace silva::app {

Handler add_bench_command(CLI::App& root) {
  auto request = std::make_shared<BenchRequest>();
  auto output = std::make_shared<OutputFlags>();
  CLI::App* cmd = root.add_subcommand(
      "bench",
      "Run the end-to-end benchmarks that reproduce the thesis tables on this machine and write "
      "bench/results/<date>-<cpu>-bench.json and a markdown report with charts; thesis Tables 5.1-5.9, the "
      "690-set autopilot and thread scaling 1..nproc, compared with the previous results.");
  cmd->add_flag("--quick", request->quick, "a short subset (about 3 minutes on 2 cores instead of about 20)");
  cmd->add_option("--out", request->out_dir, "results folder (default: bench/results of the source tree)")
      ->type_name("DIR");
  add_output_flags(*cmd, *output);
  cmd->footer("Examples:\n  silva bench --quick\n  silva bench --json > summary.json\n  silva bench --quick --out /tmp/bench");
  return [request, output] { return run_bench(*request, Reporter(*output)); };
}

}  // namespace silva::app
