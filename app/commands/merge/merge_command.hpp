#pragma once
/// @file What `silva merge` asks of the pipeline, and its run function.
#include <filesystem>

#include "pipeline/console/reporter.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

/// `silva merge DIR`: check shards cover every frame, then write manifest.json.
struct MergeRequest {
  std::filesystem::path run_dir;  ///< <output.dir>/<seed>/, an existing folder.
};

/// Merges shards of a run; returns the exit code. Throws InputError / IoError.
int run_merge(const MergeRequest& request, const Reporter& reporter);

}  // namespace silva::app
