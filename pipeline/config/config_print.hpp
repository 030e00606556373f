#pragma once
/// @file The resolved config as TOML (`silva validate --print`) and as JSON (`--json`, manifests).
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "pipeline/config/config_loader.hpp"

namespace silva::pipeline {

/// Every key as TOML, one commented line per key by section, then the config's own lighting
/// and weather presets; reading it back gives the same Config.
std::string config_to_toml(const LoadedConfig& loaded);

/// Every key as a JSON object nested by section ({"seed":…, "output":{"dir":…}, …}); the
/// config's own lighting presets under lighting.presets and weather presets under
/// lighting.weather_presets when it has any.
nlohmann::json config_to_json(const LoadedConfig& loaded);

/// A TOML basic string literal for `text` (quoted, escaped).
std::string toml_quote(std::string_view text);

}  // namespace silva::pipeline
