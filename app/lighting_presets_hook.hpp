#pragma once
/// @file Where the config loader hands a config's own [lighting.presets.<name>] tables to the
/// lighting parser (app/lighting_config.hpp, engineer "shading").
#include <string>

#include <toml++/toml.h>

namespace silva::app {

/// Checks a config's `lighting.presets` table: every entry must be a table named by a preset.
/// Throws InputError naming `source` and the preset.
void check_lighting_presets(const toml::table& presets, const std::string& source);

}  // namespace silva::app
