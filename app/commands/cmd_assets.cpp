// `silva assets build`: generate the procedural asset library.
#include <memory>

#include "app/cli/command_options.hpp"
#include "app/cli/output_check.hpp"
#include "app/cli/subcommands.hpp"
#include "app/commands/commands.hpp"

namespace silva::app {

namespace {

struct AssetsArgs {
  std::string out;
  OutputFlags output;
};

int build_assets(const AssetsArgs& args) {
  const Reporter reporter(args.output);
  AssetsBuildRequest request;
  request.out_dir = args.out;
  if (!args.out.empty()) check_writable_dir(request.out_dir);
  return run_assets_build(request, reporter);
}

}  // namespace

Handler add_assets_command(CLI::App& root) {
  auto args = std::make_shared<AssetsArgs>();
  CLI::App* assets = root.add_subcommand("assets", "Manage the procedural asset library.");
  assets->require_subcommand(1);
  CLI::App* build = assets->add_subcommand(
      "build",
      "Generate every procedural asset (trees, dead trees, stumps, grass, ferns, shrubs, rocks, "
      "logs) as .glb files plus library.json. The build runs this once into the build tree.");
  build->add_option("--out", args->out, "folder for the library (default: the library folder Silva loads)")
      ->type_name("DIR");
  add_output_flags(*build, args->output);
  build->footer("Examples:\n  silva assets build --out build/assets\n  silva assets build --json");
  return [args] { return build_assets(*args); };
}

}  // namespace silva::app
