#pragma once
/// @file What `silva generate` asks of the pipeline after the CLI has checked its inputs, and its run function.
#include <optional>

#include "pipeline/config/config_loader.hpp"
#include "pipeline/console/reporter.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

/// `--shard i/N`: this process renders the frames whose global index mod N = i.
struct Shard {
  int index = 0;  ///< i, 0 ≤ i < count
  int count = 1;  ///< N ≥ 1
};

/// `silva generate`: capture a dataset into <output.dir>/<seed>/.
struct GenerateRequest {
  LoadedConfig config;        ///< Checked; output.dir already holds --out. seed_given is false only
                              ///< for --resume without a seed (take it from the run marker).
  int threads = 1;            ///< Resolved thread count (for run.json).
  bool resume = false;        ///< --resume: continue the run in the folder.
  bool overwrite = false;     ///< --overwrite: empty <seed>/ first.
  std::optional<Shard> shard; ///< --shard i/N (seed is then explicit).
};

/// Runs the generate pipeline; returns the exit code. Throws InputError / IoError.
int run_generate(const GenerateRequest& request, const Reporter& reporter);

}  // namespace silva::app
