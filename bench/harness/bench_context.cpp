#include "bench/harness/bench_context.hpp"

#include <chrono>

#include "pipeline/console/interrupt.hpp"
#include "world/chunk_regions.hpp"
#include "bench/harness/pipeline_names.hpp"

namespace silva::bench {

void stop_if_interrupted() {
  if (interrupt_requested()) throw Interrupted("bench interrupted");
}

BenchContext make_bench_context(const BenchPlan& plan, ThesisTables thesis, std::filesystem::path scratch,
                                const Reporter& reporter, int cores) {
  ConfigSources sources;
  sources.overrides = plan.overrides;
  sources.seed = std::to_string(kBenchSeed);
  LoadedConfig base = load_config(sources);
  RunSetup setup = make_run_setup(base);
  return BenchContext{plan, std::move(base), std::move(setup), std::move(thesis), std::move(scratch), &reporter, cores};
}

Config bench_variant(const BenchContext& ctx, const std::vector<std::string>& sets) {
  ConfigSources sources;
  sources.overrides = ctx.plan.overrides;
  sources.overrides.insert(sources.overrides.end(), sets.begin(), sets.end());
  sources.seed = std::to_string(kBenchSeed);
  return load_config(sources).config;
}

std::unique_ptr<WarmWorld> warm_world(const BenchContext& ctx, const Config& cfg) {
  const SteadyClock::time_point t0 = SteadyClock::now();
  const std::vector<ChunkCoord> coords = world::default_world_chunks(cfg);
  auto w = std::unique_ptr<WarmWorld>(new WarmWorld{world::make_world_context(cfg, *ctx.setup.library), nullptr});
  w->schedule = std::make_unique<WorldSchedule>(w->world, coords.size() + 16);
  w->objects = w->schedule->warm(coords).objects;
  w->build_s = seconds_since(t0);
  return w;
}

}  // namespace silva::bench
