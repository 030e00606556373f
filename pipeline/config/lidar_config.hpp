#pragma once
/// @file TOML -> raycast::LidarPreset: the [lidar.presets.<name>] tables of configs/lidar.toml and of a
/// user config, and the preset lidar.preset selects.
#include <filesystem>
#include <map>
#include <string>

#include <toml++/toml.h>

#include "pipeline/config/loaded_config.hpp"
#include "raycast/lidar.hpp"

namespace silva::pipeline {

/// `base` overlaid with every table of `presets` (the `lidar.presets` table of a file): a table
/// starts from the preset of the same name in `base`, or from `base`'s vlp16 for a new name (from
/// the struct's defaults when `base` has none). A table sets the beams either as `elevations_deg`
/// (ascending, ring 0 first) or as `channels` spread evenly from `elevation_min_deg` to
/// `elevation_max_deg`. Throws InputError naming `file`, the preset and the key for an unknown key,
/// a wrong type, a value out of range, or beams that are not ascending; with `complete`, also for a
/// preset left without beams or with min_range not below max_range (without: the checks a table can
/// fail on its own, for a config read before the preset file).
std::map<std::string, raycast::LidarPreset> parse_lidar_presets(const toml::table& presets, const std::string& file,
                                                                std::map<std::string, raycast::LidarPreset> base = {},
                                                                bool complete = true);

/// The preset `loaded`'s lidar.preset names, from `lidar_toml` (configs/lidar.toml) overlaid with the
/// config's own [lidar.presets.<name>] tables. Throws IoError when the file cannot be read,
/// InputError when it is not TOML, a preset is malformed or the name is not a preset.
raycast::LidarPreset selected_lidar_preset(const LoadedConfig& loaded, const std::filesystem::path& lidar_toml);

}  // namespace silva::pipeline
