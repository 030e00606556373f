#include "app/cli/cli.hpp"

#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipeline/console/interrupt.hpp"
#include "app/cli/subcommands.hpp"
#include "pipeline/console/version.hpp"
#include "core/error.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

namespace {

/// Subcommands in the order --help lists them.
constexpr std::pair<const char*, Handler (*)(CLI::App&)> kCommands[] = {
    {"generate", add_generate_command}, {"world", add_world_command},
    {"validate", add_validate_command}, {"version", add_version_command},
    {"assets", add_assets_command},     {"merge", add_merge_command},
    {"export", add_export_command},     {"card", add_card_command},
    {"verify", add_verify_command},     {"bench", add_bench_command},
    {"profile", add_profile_command},   {"view", add_view_command},
};

/// Exit codes (CONTRACT.md "Command line"; `silva verify` adds 4, a dataset below its thresholds).
constexpr int kExitInternal = 1, kExitBadInput = 2, kExitIo = 3, kExitInterrupted = 130;

/// True when --json appears among the arguments (used to report errors as JSON too).
bool wants_json(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--json") == 0) return true;
  }
  return false;
}

/// Prints the one error line on stderr (and a JSON object on stdout with --json); returns `code`.
int fail(int code, const std::string& message, bool json) {
  std::cerr << "silva: error: " << message << std::endl;
  if (json) {
    std::cout << nlohmann::json{{"ok", false}, {"exit_code", code}, {"error", message}}.dump()
              << std::endl;
  }
  return code;
}

/// The error for a first argument that is not an option and names no command; "" when it is fine.
std::string unknown_command(int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return "";
  std::string names;
  for (const auto& [name, add] : kCommands) {
    if (std::strcmp(argv[1], name) == 0) return "";
    names += std::string(names.empty() ? "" : ", ") + name;
  }
  return "unknown command '" + std::string(argv[1]) + "' (commands: " + names + "; see silva --help)";
}

/// A message on one line.
std::string one_line(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return text;
}

}  // namespace

int run_cli(int argc, char** argv) {
  const bool json = wants_json(argc, argv);
  CLI::App app("Silva: seeded forest worlds with a walkable trail, captured as labelled training "
               "images (RGB, semantic, instance, depth, normal) on CPU cores only.",
               "silva");
  app.require_subcommand(1);
  app.set_version_flag("--version", version_line());
  app.footer(
      "Exit codes: 0 ok, 1 internal error, 2 bad input, 3 I/O failure, 4 verify: dataset below its thresholds,\n"
      "130 interrupted.\n"
      "Data files are found through $SILVA_DATA, else the folder compiled in; the asset library through\n"
      "$SILVA_ASSETS, else the one built. Generated meshes are kept for later runs in $SILVA_MESH_CACHE\n"
      "(off: none), else $XDG_CACHE_HOME/silva/meshes, else ~/.cache/silva/meshes.\n"
      "Examples:\n"
      "  silva generate --config configs/demo.toml --overwrite\n"
      "  silva validate --config my.toml --print\n"
      "  silva <command> --help");
  std::vector<std::pair<CLI::App*, Handler>> handlers;
  for (const auto& [name, add] : kCommands) {
    Handler handler = add(app);
    handlers.emplace_back(app.get_subcommand(name), std::move(handler));
  }
  if (const std::string unknown = unknown_command(argc, argv); !unknown.empty())
    return fail(kExitBadInput, one_line(unknown), json);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return 0;
  } catch (const CLI::CallForAllHelp&) {
    std::cout << app.help("", CLI::AppFormatMode::All);
    return 0;
  } catch (const CLI::CallForVersion&) {
    std::cout << version_line() << std::endl;
    return 0;
  } catch (const CLI::ParseError& e) {
    return fail(kExitBadInput, one_line(e.what()) + " (see silva --help)", json);
  }
  try {
    for (const auto& [command, handler] : handlers) {
      if (command->parsed()) return handler();
    }
    return fail(kExitInternal, "internal error: no subcommand ran", json);
  } catch (const InputError& e) {
    return fail(kExitBadInput, one_line(e.what()), json);
  } catch (const IoError& e) {
    return fail(kExitIo, one_line(e.what()), json);
  } catch (const std::filesystem::filesystem_error& e) {
    return fail(kExitIo, one_line(e.what()), json);
  } catch (const Interrupted& e) {
    return fail(kExitInterrupted, one_line(e.what()), json);
  } catch (const std::exception& e) {
    return fail(kExitInternal, "internal error: " + one_line(e.what()), json);
  }
}

}  // namespace silva::app
