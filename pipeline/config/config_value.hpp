#pragma once
/// @file Setting one config key from a TOML value, with the key's type and range checks.
#include <string>

#include <toml++/toml.h>

#include "pipeline/config/config_schema.hpp"

namespace silva::pipeline {

/// Sets `key` in `config` from `value`. `where` names the source for messages ("a.toml:3:7",
/// "--set camera.fov_deg=200"). Throws InputError, one line naming the source, the key, what was
/// given and what is allowed, when the type is wrong or a value is out of range or not allowed.
void assign_key(Config& config, const ConfigKey& key, const toml::node& value,
                const std::string& where);

/// A TOML value as a message shows it: its type and, for scalars, its text ("a string (\"x\")").
std::string describe_node(const toml::node& node);

}  // namespace silva::pipeline
