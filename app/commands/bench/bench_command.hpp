#pragma once
/// @file What `silva bench` asks of the harness, and its run function.
#include <filesystem>

#include "pipeline/console/reporter.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

/// `silva bench`: the end-to-end benchmark harness.
struct BenchRequest {
  bool quick = false;                 ///< --quick: a short subset.
  std::filesystem::path out_dir;      ///< --out DIR ("" = bench/results of the source tree).
};

/// Runs the benchmark harness; returns the exit code. Throws InputError / IoError.
int run_bench(const BenchRequest& request, const Reporter& reporter);

}  // namespace silva::app
