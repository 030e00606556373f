#pragma once
/// @file Checks that involve more than one config key (CONTRACT.md "Config keys").
#include <string>
#include <vector>

#include "pipeline/config/loaded_config.hpp"

namespace silva::pipeline {

/// Throws InputError (one line, naming the keys and what is allowed) when the keys disagree:
/// camera.near < camera.far; terrain.chunk_size a whole multiple of terrain.vertex_spacing and of
/// vegetation.grid_spacing; a custom sequence needs captures.poses_file; lighting.time_of_day
/// names a preset and lighting.weather a weather preset; at least one sequence is left (autopilot needs the trail); output.dir set;
/// at most 1 000 000 frames per sequence (six-digit frame numbers).
void check_config(const LoadedConfig& loaded);

/// True when `whole` is n·`part` for a whole number n ≥ 1 (to a relative 1e-9).
bool is_whole_multiple(double whole, double part);

/// Names of the lighting presets a config can select (built-in and its own), sorted. The presets
/// themselves: pipeline/config/lighting_config.hpp parse_preset_tables(loaded.lighting_presets, loaded.source).
std::vector<std::string> lighting_preset_names(const LoadedConfig& loaded);

}  // namespace silva::pipeline
