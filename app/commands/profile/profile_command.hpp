#pragma once
/// @file What `silva profile placement` asks of the profiler, and its run function.
#include <filesystem>
#include <optional>
#include <vector>

#include "pipeline/config/config_loader.hpp"
#include "pipeline/console/reporter.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

/// `silva profile placement`: a density (x elevation x trail) sweep over seeds, profiled per class.
struct ProfilePlacementRequest {
  LoadedConfig config;              ///< Checked base config; its seed is the sweep's first seed.
  int threads = 1;                  ///< Resolved thread count.
  std::optional<double> radius;     ///< --radius R around the origin (nullopt = the default world).
  std::vector<double> densities;    ///< --densities: vegetation.density values (%), each 1..25.
  int seeds = 3;                    ///< --seeds N: seeds seed, seed+1, ..., seed+N-1.
  std::vector<double> elevations;   ///< --elevations: terrain.max_elevation values (m), each 0..50.
  std::vector<bool> trails;         ///< --trail on,off: trail.enabled values.
  std::filesystem::path out_dir;    ///< --out DIR: placement.json, placement.csv, heatmaps, charts.
};

/// Profiles placement over a sweep; returns the exit code. Throws InputError / IoError.
int run_profile_placement(const ProfilePlacementRequest& request, const Reporter& reporter);

}  // namespace silva::app
