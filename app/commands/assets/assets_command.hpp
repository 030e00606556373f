#pragma once
/// @file What `silva assets build` and `silva assets sheet` ask of the pipeline, and their run functions.
#include <cstdint>
#include <filesystem>
#include <string>

#include "pipeline/console/reporter.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

/// `silva assets build`: generate the procedural asset library.
struct AssetsBuildRequest {
  std::filesystem::path out_dir;  ///< --out DIR ("" = the library folder the pipeline uses by default).
  bool glb = false;               ///< --glb: write every variant's meshes as .glb files too.
  uint32_t max_variants = UINT32_MAX;  ///< --variants N: at most N variants per generator.
};

/// `silva assets sheet`: a contact sheet of built-in asset variants.
struct AssetsSheetRequest {
  std::string kind;               ///< Kind name or factory prefix (checked by the CLI).
  int count = 6;                  ///< Variants per factory (1..64).
  int cell = 320;                 ///< Side of one view in pixels (64..2048).
  int columns = 3;                ///< Variants per row (1..16).
  uint64_t seed = 0;              ///< Asset seed.
  std::filesystem::path out;      ///< PNG file to write.
};

/// Builds the asset library; returns the exit code. Throws InputError / IoError.
int run_assets_build(const AssetsBuildRequest& request, const Reporter& reporter);
/// Renders and writes an asset contact sheet; returns the exit code. Throws IoError.
int run_assets_sheet(const AssetsSheetRequest& request, const Reporter& reporter);

}  // namespace silva::app
