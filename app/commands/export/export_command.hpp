#pragma once
/// @file What `silva export` asks of the pipeline, its run function and the format writer generate shares.
#include <filesystem>
#include <vector>

#include "io/dataset_reader.hpp"
#include "io/export_formats.hpp"
#include "pipeline/console/reporter.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

/// `silva export DIR --format F...`: convert a finished dataset.
struct ExportRequest {
  std::filesystem::path run_dir;           ///< <output.dir>/<seed>/.
  std::vector<io::ExportFormat> formats;   ///< In the order given.
  bool all = false;                        ///< --format all: every camera format, semantickitti with lidar.
  std::filesystem::path out_dir;           ///< Each format goes to <out_dir>/<format>/.
  bool overwrite = false;                  ///< --overwrite: replace an existing <out_dir>/<format>/.
  io::ExportOptions options;               ///< --copy: copy the dataset's files instead of hard-linking them.
};

/// Exports a finished dataset; returns the exit code. Throws InputError / IoError.
int run_export(const ExportRequest& request, const Reporter& reporter);

/// InputError when a format's folder <out_dir>/<format>/ would hold the dataset `run_dir` (replacing it would
/// delete the source) or lie inside the dataset anywhere but below <run_dir>/export/.
void check_export_location(const std::filesystem::path& run_dir, const std::filesystem::path& out_dir,
                           const std::vector<io::ExportFormat>& formats);

/// Writes `formats` of `dataset` into <out_dir>/<format>/ (each moved into place when complete) and returns
/// [{"format", "dir", "seconds"}, ...]. An existing non-empty target without `overwrite` is InputError,
/// checked for every format before any is written.
nlohmann::json export_formats(const io::Dataset& dataset, const std::vector<io::ExportFormat>& formats,
                              const std::filesystem::path& out_dir, bool overwrite, const io::ExportOptions& options = {});

}  // namespace silva::app
