#pragma once
/// @file Each subcommand registers its options on the CLI and hands back its handler.
#include <functional>

#include <CLI/CLI.hpp>

namespace silva::app {

/// Runs a parsed subcommand; returns the exit code, throws InputError/IoError on failure.
using Handler = std::function<int()>;

/// `silva generate` (app/commands/cmd_generate.cpp).
Handler add_generate_command(CLI::App& root);
/// `silva world` (app/commands/cmd_world.cpp).
Handler add_world_command(CLI::App& root);
/// `silva validate` (app/commands/cmd_validate.cpp).
Handler add_validate_command(CLI::App& root);
/// `silva version` (app/commands/cmd_version.cpp).
Handler add_version_command(CLI::App& root);
/// `silva assets build` (app/commands/cmd_assets.cpp).
Handler add_assets_command(CLI::App& root);
/// `silva merge` (app/commands/cmd_merge.cpp).
Handler add_merge_command(CLI::App& root);
/// `silva export` (app/commands/cmd_export.cpp).
Handler add_export_command(CLI::App& root);
/// `silva card` (app/commands/cmd_card.cpp).
Handler add_card_command(CLI::App& root);
/// `silva verify` (app/commands/cmd_verify.cpp).
Handler add_verify_command(CLI::App& root);
/// `silva bench` (app/commands/cmd_bench.cpp).
Handler add_bench_command(CLI::App& root);
/// `silva view` (app/commands/cmd_view.cpp).
Handler add_view_command(CLI::App& root);
/// `silva profile placement` (app/commands/cmd_profile.cpp).
Handler add_profile_command(CLI::App& root);

}  // namespace silva::app
