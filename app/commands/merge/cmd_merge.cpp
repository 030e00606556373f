// `silva merge DIR`: join the shards of a run into one dataset.
#include <filesystem>
#include <memory>

#include "app/cli/command_options.hpp"
#include "app/cli/subcommands.hpp"
#include "app/commands/merge/merge_command.hpp"
#include "core/error.hpp"

namespace silva::app {

namespace {

struct MergeArgs {
  std::string dir;
  OutputFlags output;
};

int merge(const MergeArgs& args) {
  const Reporter reporter(args.output);
  std::error_code ec;
  if (!std::filesystem::is_directory(args.dir, ec)) {
    throw InputError("merge: '" + args.dir + "' is not a run folder (expected <output.dir>/<seed>/)");
  }
  return run_merge(MergeRequest{args.dir}, reporter);
}

}  // namespace

Handler add_merge_command(CLI::App& root) {
  auto args = std::make_shared<MergeArgs>();
  CLI::App* cmd = root.add_subcommand(
      "merge",
      "Check that the shards written with generate --shard i/N into one run folder share one "
      "config and together cover every frame, then write its manifest.json.");
  cmd->add_option("DIR", args->dir, "the run folder <output.dir>/<seed>/")->required();
  add_output_flags(*cmd, args->output);
  cmd->footer("Examples:\n  silva merge out/0000000042");
  return [args] { return merge(*args); };
}

}  // namespace silva::app
