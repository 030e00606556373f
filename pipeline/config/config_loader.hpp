#pragma once
/// @file Loading a run configuration: TOML file, then --set overrides, then --seed, then checks.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/config/loaded_config.hpp"

namespace silva::pipeline {

/// Where the keys come from; later sources win.
struct ConfigSources {
  std::string file;                    ///< --config F; "" = built-in defaults only.
  std::vector<std::string> overrides;  ///< --set key=value, in command-line order.
  std::optional<std::string> seed;     ///< --seed N as typed.
  std::optional<std::string> output_dir;  ///< --out DIR (sets output.dir).
};

/// Loads `sources` and runs every check (types, ranges, cross-key: pipeline/config/config_checks.hpp). Does not draw a missing seed.
/// Throws InputError (exit 2) with one line naming the file/flag, key and what is allowed.
LoadedConfig load_config(const ConfigSources& sources);

/// Reads and parses a config file (per-key checks only). Throws InputError when it is missing,
/// unreadable or not valid TOML (with line and column), or holds a bad key.
LoadedConfig read_config_file(const std::string& path);

/// Parses config TOML text (per-key checks only); `source` names it in messages.
LoadedConfig parse_config_text(std::string_view text, const std::string& source);

/// Applies one `--set key=value`: the value is read by the key's type (strings bare or quoted,
/// arrays in TOML syntax, integers where a number is expected). Throws InputError.
void apply_override(LoadedConfig& loaded, std::string_view assignment);

/// Applies `--seed N` (same checks as the seed key). Throws InputError.
void apply_seed_flag(LoadedConfig& loaded, std::string_view text);

/// Draws the seed from the clock (0 … 9 999 999 999) when none was given; marks seed_from_clock.
void resolve_seed(LoadedConfig& loaded);

}  // namespace silva::pipeline
