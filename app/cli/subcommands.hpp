#pragma once
/// @file Each subcommand registers its options on the CLI and hands back its handler.
#include <functional>

#include <CLI/CLI.hpp>

namespace silva::app {

/// Runs a parsed subcommand; returns the exit code, throws InputError/IoError on failure.
using Handler = std::function<int()>;

/// `silva generate` (app/commands/generate/cmd_generate.cpp).
Handler add_generate_command(CLI::App& root);
/// `silva world` (app/commands/world/cmd_world.cpp).
Handler add_world_command(CLI::App& root);
/// `silva validate` (app/commands/validate/cmd_validate.cpp).
Handler add_validate_command(CLI::App& root);
/// `silva version` (app/commands/version/cmd_version.cpp).
Handler add_version_command(CLI::App& root);
/// `silva assets build` (app/commands/assets/cmd_assets.cpp).
Handler add_assets_command(CLI::App& root);
/// `silva merge` (app/commands/merge/cmd_merge.cpp).
Handler add_merge_command(CLI::App& root);
/// `silva export` (app/commands/export/cmd_export.cpp).
Handler add_export_command(CLI::App& root);
/// `silva card` (app/commands/card/cmd_card.cpp).
Handler add_card_command(CLI::App& root);
/// `silva verify` (app/commands/verify/cmd_verify.cpp).
Handler add_verify_command(CLI::App& root);
/// `silva bench` (app/commands/bench/cmd_bench.cpp).
Handler add_bench_command(CLI::App& root);
/// `silva view` (app/commands/view/cmd_view.cpp).
Handler add_view_command(CLI::App& root);
/// `silva profile placement` (app/commands/profile/cmd_profile.cpp).
Handler add_profile_command(CLI::App& root);

}  // namespace silva::app
