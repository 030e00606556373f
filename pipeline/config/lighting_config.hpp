#pragma once
/// @file TOML -> render::LightingPreset and render::WeatherPreset: the [lighting.presets.<name>] and
/// [lighting.weather_presets.<name>] tables of configs/lighting.toml or of a user config.
#include <map>
#include <string>

#include <toml++/toml.h>

#include "render/lighting.hpp"

namespace silva::pipeline {

/// The built-in presets overlaid with every `lighting.presets.<name>` table of `root`. Each field
/// is optional: a table starts from the built-in of the same name, or from `day` for a new name.
/// Throws InputError naming `file` and the key for an unknown field (listing the allowed keys), a
/// wrong type (naming the expected type), a value out of range, or a preset that is not a table.
std::map<std::string, render::LightingPreset> parse_lighting_presets(const toml::table& root,
                                                                     const std::string& file);

/// Same, given the `lighting.presets` table itself (as pipeline/config/config_loader.hpp keeps it).
std::map<std::string, render::LightingPreset> parse_preset_tables(const toml::table& presets,
                                                                  const std::string& file);

/// The built-in weathers overlaid with every `lighting.weather_presets.<name>` table of `root`;
/// a table starts from the built-in of the same name, or from `clear` for a new name. Errors as
/// parse_lighting_presets.
std::map<std::string, render::WeatherPreset> parse_lighting_weathers(const toml::table& root,
                                                                     const std::string& file);

/// Same, given the `lighting.weather_presets` table itself.
std::map<std::string, render::WeatherPreset> parse_weather_tables(const toml::table& weathers,
                                                                  const std::string& file);

/// Reads a lighting file (configs/lighting.toml) and parses its presets. Throws IoError if the
/// file cannot be read, InputError if it is not valid TOML or a preset is invalid.
/// Reads and parses a lighting file (limits::read_input_file); InputError naming it when it is
/// missing, not a regular file, too large or not TOML.
toml::table read_lighting_file(const std::string& path);

std::map<std::string, render::LightingPreset> load_lighting_presets(const std::string& path);

/// Reads a lighting file and parses its weather presets; errors as load_lighting_presets.
std::map<std::string, render::WeatherPreset> load_lighting_weathers(const std::string& path);

}  // namespace silva::pipeline
