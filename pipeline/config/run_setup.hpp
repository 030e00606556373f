#pragma once
/// @file What every world-building command loads before it starts: ontology, lighting preset,
/// asset library and the world context (terrain field, trail).
#include <filesystem>
#include <memory>
#include <string>

#include "pipeline/config/config_loader.hpp"
#include "assets/library.hpp"
#include "core/ontology.hpp"
#include "raycast/lidar.hpp"
#include "render/frame_lighting.hpp"
#include "world/world_context.hpp"

namespace silva::pipeline {

/// The loaded inputs of a run. Movable; `world.library` points into `library`.
struct RunSetup {
  std::unique_ptr<assets::AssetLibrary> library;  ///< Placeable assets.
  world::WorldContext world;                      ///< Config, terrain, trail, asset tables.
  Ontology ontology;                              ///< Class ids, names, colours.
  render::RunLighting lighting;                   ///< The preset lighting.time_of_day names with lighting.weather's weather, exposure, randomisation.
  std::filesystem::path library_json;             ///< The asset library manifest used.
  std::filesystem::path lighting_toml;            ///< The lighting presets file used.
  std::filesystem::path ontology_json;            ///< The ontology file used.
  raycast::LidarPreset lidar;                     ///< The LiDAR preset lidar.preset names.
  std::filesystem::path lidar_toml;               ///< The LiDAR presets file used.
};

/// The poses of trajectory.file when the run has the trajectory sequence and the key is set, else none;
/// InputError naming the file and line when it is not a valid TUM trajectory (io/tum_trajectory_file.hpp).
std::vector<TimedPose> trajectory_file_poses(const Config& config);

/// The asset library manifest: $SILVA_ASSETS/library.json when set, else the one built with
/// the binary (SILVA_ASSET_DIR). Throws InputError naming the path when it is missing.
std::filesystem::path asset_library_path();

/// Loads the run's data files into `setup`: the ontology, the lighting presets (built-in, configs/lighting.toml,
/// the config's own) and the LiDAR preset `loaded` selects. Throws InputError naming the file or key at fault.
void load_run_files(const LoadedConfig& loaded, RunSetup& setup);

/// load_run_files, then the assets and the world context for `loaded`. Throws InputError naming the file at fault.
RunSetup make_run_setup(const LoadedConfig& loaded);

/// The resolved config as TOML without output.dir: what the run marker records for `--resume`.
std::string resumable_config_text(const LoadedConfig& loaded);

/// The run's identity in its marker: a hash of the resolved config (without output.dir) and of the
/// asset library and pose file contents; a run folder continues only a run with the same identity.
std::string run_identity_hash(const LoadedConfig& loaded, const RunSetup& setup);

}  // namespace silva::pipeline
