// `silva profile placement`: time vegetation placement and overlap resolution.
#include <memory>

#include "app/command_options.hpp"
#include "app/commands.hpp"
#include "app/subcommands.hpp"

namespace silva::app {

namespace {

struct ProfileArgs {
  ConfigSources sources;
  int threads = 0;
  std::optional<double> radius;
  int repeats = 3;
  OutputFlags output;
};

int profile_placement(const ProfileArgs& args) {
  const Reporter reporter(args.output);
  ProfilePlacementRequest request;
  request.config = load_run_config(args.sources, reporter, /*draw_seed=*/true);
  request.threads = resolved_threads(args.threads);
  request.radius = args.radius;
  request.repeats = args.repeats;
  const ThreadLimit limit(args.threads);
  return run_profile_placement(request, reporter);
}

}  // namespace

Handler add_profile_command(CLI::App& root) {
  auto args = std::make_shared<ProfileArgs>();
  CLI::App* profile = root.add_subcommand("profile", "Profile one stage of the pipeline.");
  profile->require_subcommand(1);
  CLI::App* cmd = profile->add_subcommand(
      "placement",
      "Time placement + overlap resolution (objects/s per core) on the default world or a disc "
      "around the origin: one cold run, then warm repeats.");
  add_config_options(*cmd, args->sources, /*with_seed=*/true);
  add_threads_option(*cmd, args->threads);
  cmd->add_option_function<double>("--radius", [args](double r) { args->radius = r; },
                                   "place the chunks within R metres of the origin (default: the default world)")
      ->type_name("R")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--repeat", args->repeats, "warm runs after the cold one (default 3)")
      ->type_name("N")
      ->check(CLI::Range(1, 1000));
  add_output_flags(*cmd, args->output);
  cmd->footer("Examples:\n  silva profile placement --seed 1 --threads 1\n  silva profile placement --radius 128 --json");
  return [args] { return profile_placement(*args); };
}

}  // namespace silva::app
