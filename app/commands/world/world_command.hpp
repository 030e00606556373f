#pragma once
/// @file What `silva world` asks of the pipeline after the CLI has checked its inputs, and its run function.
#include <filesystem>
#include <optional>

#include "pipeline/config/config_loader.hpp"
#include "pipeline/console/reporter.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

/// `silva world`: build the world (default or a disc), optionally export glTF, report stats.
struct WorldRequest {
  /// `--center x,y --radius R`: build the chunks intersecting this disc.
  struct Disc {
    double x = 0, y = 0, radius = 0;  ///< Centre (m) and radius (m, > 0).
  };
  LoadedConfig config;              ///< Checked, seed resolved.
  int threads = 1;                  ///< Resolved thread count.
  std::optional<Disc> region;       ///< nullopt: the default world (CONTRACT.md).
  std::filesystem::path export_path;  ///< --export FILE.glb ("" = no export).
  bool instancing = false;          ///< --instancing: EXT_mesh_gpu_instancing in the export.
  std::filesystem::path map_path;   ///< --map FILE.png: top-down class map ("" = none).
  bool stats = false;               ///< --stats: print counts and timings.
};

/// Builds (and exports) a world; returns the exit code. Throws InputError / IoError.
int run_world(const WorldRequest& request, const Reporter& reporter);

}  // namespace silva::app
