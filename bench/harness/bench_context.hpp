#pragma once
/// @file What every measurement of `silva bench` shares: the base config, the loaded inputs (asset
/// library loaded once), the thesis tables, the sweep sizes and a scratch folder for captures.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "pipeline/console/reporter.hpp"
#include "pipeline/config/config_loader.hpp"
#include "pipeline/config/run_setup.hpp"
#include "pipeline/schedule/world_schedule.hpp"
#include "bench/harness/bench_figures.hpp"
#include "bench/harness/bench_plan.hpp"
#include "core/stopwatch.hpp"
#include "bench/harness/pipeline_names.hpp"

namespace silva::bench {

/// Fixed seed of every harness world (results are comparable run to run).
inline constexpr int64_t kBenchSeed = 1234567890;

/// The shared state of one harness run.
struct BenchContext {
  BenchPlan plan;                  ///< Sweep sizes.
  LoadedConfig base;               ///< Built-in defaults + plan overrides + kBenchSeed.
  RunSetup setup;                  ///< Inputs of the base config (library, ontology, day preset).
  ThesisTables thesis;             ///< The thesis's figures.
  std::filesystem::path scratch;   ///< Temporary folder for capture output (deleted by the caller).
  const Reporter* reporter = nullptr;  ///< Progress notes.
  int cores = 1;                   ///< Threads for the non-scaling measurements.
};

/// Loads the base config and inputs for `plan`. Throws InputError on a bad override.
BenchContext make_bench_context(const BenchPlan& plan, ThesisTables thesis, std::filesystem::path scratch,
                                const Reporter& reporter, int cores);

/// The base config with `sets` (`key=value`, as for --set) applied and checked.
Config bench_variant(const BenchContext& ctx, const std::vector<std::string>& sets);

/// A world whose every default-world chunk is generated and cached (capture figures are timed warm).
struct WarmWorld {
  world::WorldContext world;                ///< Context of the variant config.
  std::unique_ptr<WorldSchedule> schedule;  ///< Its chunk cache holds the whole default world.
  double build_s = 0;         ///< Time to generate it (not part of any capture figure).
  uint64_t objects = 0;       ///< Objects in the world.
};

/// Builds the variant `cfg` and fills its cache with the default world.
std::unique_ptr<WarmWorld> warm_world(const BenchContext& ctx, const Config& cfg);

/// Throws Interrupted when Ctrl-C (SIGINT/SIGTERM) asked the harness to stop.
void stop_if_interrupted();

}  // namespace silva::bench
