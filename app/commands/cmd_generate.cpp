// `silva generate`: check every input, then run the capture pipeline.
#include <charconv>
#include <memory>

#include "app/cli/command_options.hpp"
#include "app/cli/interrupt.hpp"
#include "app/cli/output_check.hpp"
#include "app/cli/subcommands.hpp"
#include "app/commands/commands.hpp"
#include "core/error.hpp"

namespace silva::app {

namespace {

struct GenerateArgs {
  ConfigSources sources;
  int threads = 0;
  bool resume = false;
  bool overwrite = false;
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

int generate(const GenerateArgs& args) {
  const Reporter reporter(args.output);
  GenerateRequest request;
  // Shards of one dataset must agree on the seed, so a shard never draws one from the clock.
  const bool draw_seed = !args.resume && !args.shard;
  request.config = load_run_config(args.sources, reporter, draw_seed);
  if (args.shard) {
    request.shard = parse_shard(*args.shard);
    if (!request.config.seed_given) {
      throw InputError("--shard " + *args.shard + " needs an explicit seed (--seed N or seed in the config)");
    }
  }
  check_writable_dir(request.config.config.output.dir);
  request.threads = resolved_threads(args.threads);
  request.resume = args.resume;
  request.overwrite = args.overwrite;
  const ThreadLimit limit(args.threads);
  install_interrupt_handler();
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
