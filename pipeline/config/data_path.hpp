#pragma once
/// @file Where Silva's data files (configs, ontology, asset library) live.
#include <filesystem>
#include <string>

namespace silva::pipeline {

/// The data folder: $SILVA_DATA when set and non-empty, else the SILVA_DATA_DIR compiled in.
std::filesystem::path data_root();

/// A data file by its path relative to the data folder, e.g. data_path("configs/lighting.toml").
std::filesystem::path data_path(const std::string& relative);

}  // namespace silva::pipeline
