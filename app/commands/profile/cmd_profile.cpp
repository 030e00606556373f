// `silva profile placement`: what a density gives (objects per class, canopy, spacing) and what it costs.
#include <memory>

#include "app/cli/command_options.hpp"
#include "app/cli/subcommands.hpp"
#include "app/commands/profile/profile_command.hpp"
#include "core/error.hpp"

namespace silva::app {

namespace {

struct ProfileArgs {
  ConfigSources sources;
  int threads = 0;
  std::optional<double> radius;
  std::vector<double> densities = {1, 5, 10, 20, 25};
  int seeds = 3;
  std::vector<double> elevations;
  std::vector<std::string> trails;
  std::string out = "profile-placement";
  OutputFlags output;
};

/// Checks that every value of `flag` lies in [lo, hi].
void check_range(const char* flag, const std::vector<double>& values, double lo, double hi) {
  for (double v : values)
    if (!(v >= lo && v <= hi))
      throw InputError(std::string(flag) + " " + std::to_string(v) + ": each value must be in " + std::to_string(lo) +
                       " .. " + std::to_string(hi));
}

/// "on"/"off" (or true/false) values of --trail.
std::vector<bool> parse_trails(const std::vector<std::string>& values) {
  std::vector<bool> out;
  for (const std::string& v : values) {
    if (v == "on" || v == "true") out.push_back(true);
    else if (v == "off" || v == "false") out.push_back(false);
    else throw InputError("--trail " + v + ": expected on, off or on,off");
  }
  return out;
}

int profile_placement(const ProfileArgs& args) {
  const Reporter reporter(args.output);
  ProfilePlacementRequest request;
  request.config = load_run_config(args.sources, reporter, /*draw_seed=*/true);
  const Config& cfg = request.config.config;
  check_range("--densities", args.densities, 1, 25);
  check_range("--elevations", args.elevations, 0, 50);
  request.threads = resolved_threads(args.threads);
  request.radius = args.radius;
  request.densities = args.densities;
  request.seeds = args.seeds;
  request.elevations = args.elevations.empty() ? std::vector<double>{cfg.terrain.max_elevation} : args.elevations;
  request.trails = args.trails.empty() ? std::vector<bool>{cfg.trail.enabled} : parse_trails(args.trails);
  request.out_dir = args.out;
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
      "Sweep vegetation density (and optionally elevation and trail on/off) over seeds and report per class "
      "what you get (objects per hectare, canopy cover, adjusted/dropped, nearest-neighbour spacing) and what "
      "it costs (FCL queries, ms per chunk per phase): placement.json, placement.csv, charts and one top-down "
      "density heatmap per density.");
  add_config_options(*cmd, args->sources, /*with_seed=*/true);
  add_threads_option(*cmd, args->threads);
  cmd->add_option_function<double>("--radius", [args](double r) { args->radius = r; },
                                   "profile the chunks within R metres of the origin (default: the default world)")
      ->type_name("R")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--densities", args->densities, "vegetation.density values, % (default 1,5,10,20,25)")
      ->delimiter(',')
      ->type_name("D,...");
  cmd->add_option("--seeds", args->seeds, "worlds per setting: seeds seed .. seed+N-1 (default 3)")
      ->type_name("N")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--elevations", args->elevations, "terrain.max_elevation values, metres (default: the config's)")
      ->delimiter(',')
      ->type_name("M,...");
  cmd->add_option("--trail", args->trails, "trail.enabled values: on, off or on,off (default: the config's)")
      ->delimiter(',')
      ->type_name("on,off");
  cmd->add_option("--out", args->out, "output folder (default profile-placement)")->type_name("DIR");
  add_output_flags(*cmd, args->output);
  cmd->footer(
      "Examples:\n  silva profile placement --seed 1 --radius 128\n"
      "  silva profile placement --densities 5,25 --seeds 2 --trail on,off --out /tmp/profile --json");
  return [args] { return profile_placement(*args); };
}

}  // namespace silva::app
