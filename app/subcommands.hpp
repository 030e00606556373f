#pragma once
/// @file Each subcommand registers its options on the CLI and hands back its handler.
#include <functional>

#include <CLI/CLI.hpp>

namespace silva::app {

/// Runs a parsed subcommand; returns the exit code, throws InputError/IoError on failure.
using Handler = std::function<int()>;

/// `silva generate` (app/cmd_generate.cpp).
Handler add_generate_command(CLI::App& root);
/// `silva world` (app/cmd_world.cpp).
Handler add_world_command(CLI::App& root);
/// `silva validate` (app/cmd_validate.cpp).
Handler add_validate_command(CLI::App& root);
/// `silva version` (app/cmd_version.cpp).
Handler add_version_command(CLI::App& root);
/// `silva assets build` (app/cmd_assets.cpp).
Handler add_assets_command(CLI::App& root);
/// `silva merge` (app/cmd_merge.cpp).
Handler add_merge_command(CLI::App& root);
/// `silva bench` (app/cmd_bench.cpp).
Handler add_bench_command(CLI::App& root);
/// `silva profile placement` (app/cmd_profile.cpp).
Handler add_profile_command(CLI::App& root);

}  // namespace silva::app
