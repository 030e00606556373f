// `silva assets build` (generate the procedural asset library) and `silva assets sheet` (contact sheets).
#include <memory>
#include <string>

#include "app/cli/command_options.hpp"
#include "app/cli/output_check.hpp"
#include "app/cli/subcommands.hpp"
#include "app/commands/assets/asset_sheet.hpp"
#include "app/commands/assets/assets_command.hpp"
#include "assets/factory.hpp"
#include "core/error.hpp"

namespace silva::app {

namespace {

struct AssetsArgs {
  std::string out;
  bool glb = false;
  uint32_t max_variants = UINT32_MAX;
  OutputFlags output;
};

struct SheetArgs {
  AssetsSheetRequest request;
  std::string out;
  OutputFlags output;
};

/// Every name `silva assets sheet --kind` accepts: kind names, then factory prefixes.
std::string sheet_names() {
  std::string kinds, prefixes;
  for (const assets::Factory& f : assets::factories()) {
    const std::string kind = assets::kind_name(f.kind);
    if (kinds.find(kind) == std::string::npos) kinds += (kinds.empty() ? "" : ", ") + kind;
    prefixes += std::string(prefixes.empty() ? "" : ", ") + f.prefix;
  }
  return kinds + "; or one generator: " + prefixes;
}

int sheet_assets(SheetArgs& args) {
  const Reporter reporter(args.output);
  if (select_factories(args.request.kind).empty())
    throw InputError("--kind " + args.request.kind + ": unknown name; expected kinds or generators, comma-separated (" +
                     sheet_names() + ")");
  args.request.out = args.out;
  if (args.request.out.extension() != ".png") throw InputError("--out " + args.out + ": expected a .png file");
  const auto parent = args.request.out.parent_path();
  if (!parent.empty()) check_writable_dir(parent);
  return run_assets_sheet(args.request, reporter);
}

int build_assets(const AssetsArgs& args) {
  const Reporter reporter(args.output);
  AssetsBuildRequest request;
  request.out_dir = args.out;
  request.glb = args.glb;
  request.max_variants = args.max_variants;
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
      "Generate every procedural asset variant and write library.json: each variant's class, collision "
      "proxy and LOD thresholds, while its meshes are generated again when a run first draws it. "
      "--glb also writes every variant as a .glb file (to inspect, edit or replace). The build runs "
      "this once into the build tree.");
  build->add_option("--out", args->out, "folder for the library (default: the library folder Silva loads)")
      ->type_name("DIR");
  build->add_flag("--glb", args->glb, "also write each variant's LOD meshes as <name>.glb (file entries)");
  build->add_option("--variants", args->max_variants, "at most N variants per generator (default: all)")
      ->check(CLI::Range(1, 1000))
      ->type_name("N");
  add_output_flags(*build, args->output);
  build->footer("Examples:\n  silva assets build --out build/assets\n  silva assets build --glb --out my-assets --json");

  auto sheet_args = std::make_shared<SheetArgs>();
  sheet_args->request.seed = assets::kDefaultAssetSeed;
  CLI::App* sheet = assets->add_subcommand(
      "sheet",
      "Render a contact sheet of built-in asset variants: each variant alone on a flat forest floor "
      "in the day preset, its RGB view beside its semantic colours, variants row by row.");
  sheet->add_option("--kind", sheet_args->request.kind,
                    "comma-separated kinds or generators (" + sheet_names() + ")")
      ->required()
      ->type_name("NAME");
  sheet->add_option("--out", sheet_args->out, "PNG file to write")->required()->type_name("FILE.png");
  sheet->add_option("--count", sheet_args->request.count, "variants per generator (default 6)")
      ->check(CLI::Range(1, 64));
  sheet->add_option("--cell", sheet_args->request.cell, "side of one view in pixels (default 320)")
      ->check(CLI::Range(64, 2048));
  sheet->add_option("--columns", sheet_args->request.columns, "variants per row (default 3)")
      ->check(CLI::Range(1, 16));
  sheet->add_option("--seed", sheet_args->request.seed, "asset seed (default: the library's)");
  add_output_flags(*sheet, sheet_args->output);
  sheet->footer("Examples:\n  silva assets sheet --kind conifer_tree --out conifers.png\n"
                "  silva assets sheet --kind rock --count 9 --columns 3 --out rocks.png\n"
                "  silva assets sheet --kind conifer_tree,broadleaf_tree --count 4 --columns 4 --out trees.png "
                "(one row per generator)");
  return [args, sheet_args, build] {  // exactly one of build, sheet was parsed (require_subcommand(1))
    if (build->parsed()) return build_assets(*args);
    return sheet_assets(*sheet_args);
  };
}

}  // namespace silva::app
