// `silva generate`: check every input, then run the capture pipeline.
#include <charconv>
#include <memory>

#include "app/cli/command_options.hpp"
#include "pipeline/console/interrupt.hpp"
#include "app/cli/output_check.hpp"
#include "app/cli/subcommands.hpp"
#include "app/commands/generate/generate_command.hpp"
#include "pipeline/config/config_checks.hpp"
#include "pipeline/config/cost_estimate.hpp"
#include "core/error.hpp"
#include "io/run_folder.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

namespace {

struct GenerateArgs {
  ConfigSources sources;
  int threads = 0;
  bool resume = false;
  bool overwrite = false;
  bool force = false;
  std::optional<std::string> shard;
  OutputFlags output;
};

/// Parses a whole non-empty decimal number that is all of `text`.
bool parse_int(std::string_view text, int& out) {
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, out);
  return !text.empty() && result.ec == std::errc{} && result.ptr == end;
}

/// Parses "i/N" with 0 ≤ i < N.
Shard parse_shard(const std::string& text) {
  Shard shard;
  const size_t slash = text.find('/');
  const std::string_view view = text;
  const bool ok = slash != std::string::npos && parse_int(view.substr(0, slash), shard.index) &&
                  parse_int(view.substr(slash + 1), shard.count) && shard.index >= 0 &&
                  shard.index < shard.count;
  if (!ok) throw InputError("--shard " + text + ": expected i/N with 0 <= i < N, e.g. --shard 0/4");
  return shard;
}

/// `--resume` with neither --config nor --set: the config the run folder's marker records (so the
/// interrupt hint `silva generate --resume --out DIR --seed N` continues exactly that run); the defaults when
/// the marker records no config. InputError when there is no run folder to resume.
LoadedConfig config_to_resume(const ConfigSources& sources) {
  LoadedConfig given = load_config(sources);
  const std::string dir = given.config.output.dir;
  const int64_t seed = given.seed_given ? given.config.seed : io::find_resumable_seed(dir);
  const std::filesystem::path run_dir = std::filesystem::path(dir) / io::seed_folder_name(seed);
  const std::optional<io::RunMarker> marker = io::read_run_marker(run_dir);
  if (!marker)
    throw InputError(run_dir.string() + ": nothing to resume (no run folder with a .silva-run.json there); drop "
                     "--resume to start a new run, or name the run with --out and --seed");
  if (marker->config.empty()) return given;
  LoadedConfig loaded = parse_config_text(marker->config, (run_dir / ".silva-run.json").string());
  loaded.config.output.dir = dir;
  loaded.config.seed = seed;
  loaded.seed_given = true;
  check_config(loaded);
  return loaded;
}

int generate(const GenerateArgs& args) {
  install_interrupt_handler();  // from the start: loading and planning stop at once too
  const Reporter reporter(args.output);
  GenerateRequest request;
  // Shards of one dataset must agree on the seed, so a shard never draws one from the clock.
  const bool draw_seed = !args.resume && !args.shard;
  const bool config_from_marker = args.resume && args.sources.file.empty() && args.sources.overrides.empty();
  request.config =
      config_from_marker ? config_to_resume(args.sources) : load_run_config(args.sources, reporter, draw_seed);
  if (args.shard) {
    request.shard = parse_shard(*args.shard);
    if (!request.config.seed_given) {
      throw InputError("--shard " + *args.shard + " needs an explicit seed (--seed N or seed in the config)");
    }
  }
  check_cost(estimate_generate_cost(request.config.config), args.force, "generate");
  check_writable_dir(request.config.config.output.dir);
  request.threads = resolved_threads(args.threads);
  request.resume = args.resume;
  request.overwrite = args.overwrite;
  const ThreadLimit limit(args.threads);
  return run_generate(request, reporter);
}

}  // namespace

Handler add_generate_command(CLI::App& root) {
  auto args = std::make_shared<GenerateArgs>();
  CLI::App* cmd = root.add_subcommand(
      "generate",
      "Generate a seeded forest world and capture a labelled dataset (rgb, semantic, instance, "
      "depth, normal, camera files) into <output.dir>/<seed>/. An existing run folder needs "
      "--resume or --overwrite.");
  add_config_options(*cmd, args->sources, /*with_seed=*/true);
  cmd->add_option_function<std::string>(
         "--out", [args](const std::string& dir) { args->sources.output_dir = dir; },
         "output folder (overrides output.dir); the run goes to DIR/<seed>/")
      ->type_name("DIR");
  add_threads_option(*cmd, args->threads);
  CLI::Option* resume = cmd->add_flag(
      "--resume", args->resume,
      "continue the run already in the folder (seed taken from its marker when not given)");
  cmd->add_flag("--overwrite", args->overwrite, "empty <output.dir>/<seed>/ first")->excludes(resume);
  cmd->add_flag("--force", args->force,
                "run even when the cost estimate (memory, placement work per frame) exceeds this machine");
  cmd->add_option_function<std::string>(
         "--shard", [args](const std::string& s) { args->shard = s; },
         "render only frames whose global index mod N = i (needs an explicit seed; finish with "
         "silva merge)")
      ->type_name("i/N");
  add_output_flags(*cmd, args->output);
  cmd->footer(
      "Examples:\n"
      "  silva generate                                  # thesis defaults: 790 captures, 1920x1080\n"
      "  silva generate --config configs/demo.toml --overwrite\n"
      "  silva generate --seed 42 --set captures.random_count=10 --set 'captures.sequences=[\"random\"]'\n"
      "  silva generate --seed 42 --shard 0/4           # then: silva merge out/0000000042");
  return [args] { return generate(*args); };
}

}  // namespace silva::app
