#pragma once
/// @file A resolved configuration and what it was made from (what the loader produces and the
/// checks read).
#include <set>
#include <string>

#include <toml++/toml.h>

#include "core/config.hpp"

namespace silva::pipeline {

/// A resolved configuration and what it was made from.
struct LoadedConfig {
  Config config;                 ///< Every key, resolved.
  bool seed_given = false;       ///< True when the seed came from the file, --set or --seed.
  bool seed_from_clock = false;  ///< True when resolve_seed drew the seed from the clock.
  std::string source;            ///< The config file as given, "" for the built-in defaults.
  std::set<std::string> keys_set;  ///< Keys the file or --set gave (a rig preset fills the rig.* keys left out).
  toml::table lighting_presets;  ///< The config's [lighting.presets.<name>] tables, as written
                                 ///< (already checked by parse_preset_tables).
  toml::table weather_presets;   ///< The config's [lighting.weather_presets.<name>] tables, as written
                                 ///< (already checked by parse_weather_tables).
  toml::table lidar_presets;     ///< The config's [lidar.presets.<name>] tables, as written
                                 ///< (already checked by parse_lidar_presets).
};

}  // namespace silva::pipeline
