// `silva card DIR`: describe a finished dataset in CARD.md, card.json and charts.
#include <memory>

#include "app/cli/command_options.hpp"
#include "app/cli/subcommands.hpp"
#include "app/commands/card/card_command.hpp"

namespace silva::app {

namespace {

struct CardArgs {
  std::string dir;
  int threads = 0;
  OutputFlags output;
};

}  // namespace

Handler add_card_command(CLI::App& root) {
  auto args = std::make_shared<CardArgs>();
  CLI::App* cmd = root.add_subcommand(
      "card",
      "Write DIR/CARD.md, DIR/card.json and charts DIR/card_*.png: class pixel fractions, instance counts and "
      "sizes, a depth histogram, the camera positions, conditions, config differences from the defaults.");
  cmd->add_option("DIR", args->dir, "the dataset folder <output.dir>/<seed>/")->required();
  add_threads_option(*cmd, args->threads);
  add_output_flags(*cmd, args->output);
  cmd->footer("Examples:\n  silva card out/1234567890");
  return [args] {
    const Reporter reporter(args->output);
    const ThreadLimit limit(args->threads);
    return run_card(args->dir, reporter);
  };
}

}  // namespace silva::app
