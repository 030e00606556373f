// World generation benchmarks (thesis Tables 5.1, 5.2, 5.4, 5.4b): seed -> every chunk of the
// default world generated, placed and resolved through the ECS world (one frame of Stream ->
// Generate -> Place -> Resolve over the pinned default-world chunks), with object counts as
// counters, on 1 and 2 threads.
// The asset library is the built-in procedural one (assets::generate_library), built once
// outside the timed region.
#include <benchmark/benchmark.h>

#include <map>

#include "assets/factory.hpp"
#include "world/chunk_regions.hpp"
#include "world/placement.hpp"
#include "world/resolve.hpp"
#include "pipeline/schedule/world_schedule.hpp"

namespace {

using namespace silva;

/// The built-in asset library, generated once.
const assets::AssetLibrary& library() {
  static const assets::AssetLibrary lib = assets::generate_library();
  return lib;
}

/// Seed of every benchmark world.
constexpr int64_t kSeed = 1234567890;

/// Publishes a world's totals as counters.
void report(benchmark::State& state, const world::BuiltWorld& w, int threads) {
  const auto& t = w.totals;
  state.counters["chunks"] = double(t.chunks);
  state.counters["triangles"] = double(t.triangles);
  state.counters["objects"] = double(t.objects);
  state.counters["trees"] = double(t.objects_by_role[size_t(Role::TreeTrunk)]);
  state.counters["dead_trees"] = double(t.objects_by_role[size_t(Role::DeadTree)]);
  state.counters["stumps"] = double(t.objects_by_role[size_t(Role::Stump)]);
  state.counters["shrubs"] = double(t.objects_by_role[size_t(Role::Shrub)]);
  state.counters["obstacles"] = double(t.objects_by_role[size_t(Role::Obstacle)]);
  state.counters["ground_veg"] = double(t.objects_by_role[size_t(Role::GroundVegetation)]);
  state.counters["adjusted"] = double(t.adjusted);
  state.counters["dropped"] = double(t.dropped);
  state.counters["narrow_queries"] = double(t.narrow_queries);
  state.counters["broad_queries"] = double(t.broad_queries);
  state.counters["place_s"] = t.place_s;
  state.counters["chunks_s"] = t.chunks_s;
  state.counters["terrain_cpu_s"] = t.terrain_cpu_s;
  state.counters["resolve_cpu_s"] = t.resolve_cpu_s;
  state.counters["threads"] = threads;
  // Placement + resolve throughput per core: final objects over the CPU time of the two phases.
  const double place_resolve_cpu = t.place_s * threads + t.resolve_cpu_s;
  state.counters["objects_per_s_per_core"] = place_resolve_cpu > 0 ? double(t.objects) / place_resolve_cpu : 0;
}

/// Builds the default world of `cfg` once per iteration on `threads` threads.
void run_default_world(benchmark::State& state, const Config& cfg, int threads) {
  library();
  world::BuiltWorld w;
  for (auto _ : state) {
    const world::WorldContext ctx = world::make_world_context(cfg, library());
    w = pipeline::build_default_world(ctx, threads);
    benchmark::DoNotOptimize(w.hash);
  }
  report(state, w, threads);
}

/// Table 5.1: vegetation density (percent) x threads.
void BM_DefaultWorld_Density(benchmark::State& state) {
  Config cfg;
  cfg.seed = kSeed;
  cfg.vegetation.density = double(state.range(0));
  run_default_world(state, cfg, int(state.range(1)));
}
BENCHMARK(BM_DefaultWorld_Density)
    ->ArgsProduct({{1, 5, 10, 20, 25}, {1, 2}})
    ->ArgNames({"density", "threads"})
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);

/// Table 5.2: max terrain elevation (centimetres) x threads.
void BM_DefaultWorld_Elevation(benchmark::State& state) {
  Config cfg;
  cfg.seed = kSeed;
  cfg.terrain.max_elevation = double(state.range(0)) / 100.0;
  run_default_world(state, cfg, int(state.range(1)));
}
BENCHMARK(BM_DefaultWorld_Elevation)
    ->ArgsProduct({{5, 50, 100, 150, 250, 350}, {1, 2}})
    ->ArgNames({"elevation_cm", "threads"})
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);

/// Table 5.4: trail on / off x threads.
void BM_DefaultWorld_Trail(benchmark::State& state) {
  Config cfg;
  cfg.seed = kSeed;
  cfg.trail.enabled = state.range(0) != 0;
  run_default_world(state, cfg, int(state.range(1)));
}
BENCHMARK(BM_DefaultWorld_Trail)
    ->ArgsProduct({{1, 0}, {1, 2}})
    ->ArgNames({"trail", "threads"})
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);

/// Table 5.4b: no ground vegetation, 2 threads.
void BM_DefaultWorld_NoGroundVegetation(benchmark::State& state) {
  Config cfg;
  cfg.seed = kSeed;
  cfg.vegetation.ground = false;
  run_default_world(state, cfg, 2);
}
BENCHMARK(BM_DefaultWorld_NoGroundVegetation)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);

/// Placement + resolve only (no meshes) on one thread over the chunks of a 128 m disc: every
/// chunk's candidates (with ground vegetation) and its neighbour ring's (solids) placed once,
/// then every chunk resolved; objects/s per core.
void BM_PlaceResolve_OneCore(benchmark::State& state) {
  Config cfg;
  cfg.seed = kSeed;
  cfg.vegetation.density = double(state.range(0));
  const world::WorldContext ctx = world::make_world_context(cfg, library());
  const auto coords = world::chunks_in_disc(0, 0, 128, cfg.terrain.chunk_size);
  const int ring = ctx.neighbour_ring;
  uint64_t objects = 0;
  for (auto _ : state) {
    std::map<ChunkCoord, world::ChunkCandidates> table;
    for (ChunkCoord c : coords) table[c] = world::place_candidates(ctx, c, true);
    for (ChunkCoord c : coords)
      for (int dj = -ring; dj <= ring; ++dj)
        for (int di = -ring; di <= ring; ++di) {
          const ChunkCoord n{c.i + di, c.j + dj};
          if (!table.count(n)) table[n] = world::place_candidates(ctx, n, false);
        }
    const world::CandidateLookup lookup = [&](ChunkCoord n) -> const world::ChunkCandidates& { return table.at(n); };
    objects = 0;
    for (ChunkCoord c : coords) {
      world::ResolveStats rs;
      objects += world::resolve_chunk(ctx, c, table.at(c), lookup, rs).size();
    }
  }
  state.counters["objects"] = double(objects);
  state.counters["objects_per_s"] = benchmark::Counter(double(objects), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_PlaceResolve_OneCore)->ArgName("density")->Arg(5)->Arg(25)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
