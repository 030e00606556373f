// Rasteriser benchmark: visibility pass and visibility + resolve at 1920x1080, 1 and 2 threads, on
// the views of bench/bench_views.hpp (argument `view`): 0 = the synthetic stress forest of
// bench/forest_scene.hpp (128 m x 128 m terrain at 0.5 m, 300 instanced trees of ~2-4k triangles
// with alpha-tested leaf cards, LODs off), 1 = the default world's middle autopilot view (LODs on).
// Fixed seeds; work counts beside times.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

#include <tbb/task_arena.h>

#include "bench/bench_views.hpp"
#include "core/stopwatch.hpp"
#include "render/raster_conventions.hpp"
#include "render/renderer.hpp"

namespace {

using namespace silva;
using namespace silva::render;

/// Adds the work counters of a frame and the rates derived from them.
void report(benchmark::State& state, const RenderStats& s, double pixels, double cold_ms) {
  state.counters["tri_submitted"] = double(s.triangles_submitted);
  state.counters["tri_after_cull"] = double(s.triangles_after_cull);
  state.counters["tri_rasterised"] = double(s.triangles_rasterised);
  state.counters["px_written"] = double(s.pixels_shaded_or_written);
  state.counters["px_covered"] = double(s.pixels_covered);
  state.counters["cold_ms"] = cold_ms;
  state.counters["ms_per_frame"] = benchmark::Counter(1e-3, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["Mtri_per_s"] = benchmark::Counter(double(s.triangles_submitted) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["Mpix_per_s"] = benchmark::Counter(pixels * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

/// Number of distinct (instance, triangle) pairs that own at least one pixel of `vis`: how much
/// of the rasterised geometry ends up visible.
double visible_triangles(const VisibilityBuffer& vis) {
  std::vector<uint64_t> keys;
  keys.reserve(vis.size());
  for (size_t i = 0; i < vis.size(); ++i)
    if (vis.instance[i] != kNoInstance) keys.push_back(uint64_t(vis.instance[i]) << 32 | vis.triangle[i]);
  std::sort(keys.begin(), keys.end());
  return double(std::unique(keys.begin(), keys.end()) - keys.begin());
}

/// One frame of view state.range(0) per iteration in an arena of state.range(1) threads; resolve
/// when `gbuffer`.
void run(benchmark::State& state, bool gbuffer) {
  const bench::BenchView v = bench::bench_view(state.range(0));
  const Scene& scene = *v.silva_scene;
  const Camera& camera = *v.peers.camera;
  tbb::task_arena arena(int(state.range(1)));
  Renderer renderer;
  GBuffer g;
  RenderStats stats;
  const RenderOptions opt = v.options();
  const auto frame = [&] {
    arena.execute([&] {
      if (gbuffer) {
        renderer.render_gbuffer(scene, camera, opt, g, &stats);
      } else {
        renderer.render_visibility(scene, camera, opt, &stats);
      }
    });
  };
  const Stopwatch clock;
  frame();  // cold: first frame grows every buffer
  const double cold_ms = 1000 * clock.seconds();
  for (auto _ : state) frame();
  report(state, stats, double(camera.width) * double(camera.height), cold_ms);
  if (!gbuffer) state.counters["tri_visible"] = visible_triangles(renderer.render_visibility(scene, camera, opt));
}

void BM_RasterVisibility(benchmark::State& state) { run(state, false); }
void BM_RasterVisibilityResolve(benchmark::State& state) { run(state, true); }

}  // namespace

BENCHMARK(BM_RasterVisibility)->Apply(bench::views_and_threads);
BENCHMARK(BM_RasterVisibilityResolve)->Apply(bench::views_and_threads);
