// `silva view`: parse the options, then serve the explorer page.
#include <memory>

#include "app/cli/command_options.hpp"
#include "pipeline/console/interrupt.hpp"
#include "app/cli/subcommands.hpp"
#include "app/commands/view/view_command.hpp"
#include "core/error.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

namespace {

struct ViewArgs {
  ViewRequest request;
  int threads = 0;
  OutputFlags output;
};

int view(const ViewArgs& args) {
  const Reporter reporter(args.output);
  if (args.request.port < 0 || args.request.port > 65535)
    throw InputError("--port " + std::to_string(args.request.port) + ": allowed 0 .. 65535 (0 = any free port)");
  const ThreadLimit limit(args.threads);
  install_interrupt_handler();
  return run_view(args.request, reporter);
}

}  // namespace

Handler add_view_command(CLI::App& root) {
  auto args = std::make_shared<ViewArgs>();
  CLI::App* cmd = root.add_subcommand(
      "view",
      "Explore the world in a web browser before generating it: a local page renders it from a free "
      "camera (RGB, semantic, instance, depth, normal), edits the config, and captures the current "
      "view as a custom frame into <output.dir>/<seed>/. Prints the URL; Ctrl-C stops (exit 130).");
  add_config_options(*cmd, args->request.sources, /*with_seed=*/true);
  cmd->add_option("--port", args->request.port, "port to listen on (0 = any free port; the URL is printed)")
      ->type_name("P");
  cmd->add_option("--host", args->request.host,
                  "address to listen on (default 127.0.0.1: this machine only; anything else exposes the page)")
      ->type_name("ADDR");
  add_threads_option(*cmd, args->threads);
  add_output_flags(*cmd, args->output);
  cmd->footer(
      "Examples:\n"
      "  silva view --config configs/demo.toml        # then open the printed URL\n"
      "  silva view --seed 42 --port 0                 # any free port\n"
      "  ssh -L 8080:127.0.0.1:8080 cluster-node       # view a remote machine's page locally");
  return [args] { return view(*args); };
}

}  // namespace silva::app
