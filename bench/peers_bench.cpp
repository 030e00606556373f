// Peers benchmark: Silva's visibility pass against Mesa llvmpipe (OpenGL on the CPU) and Embree 3
// (one primary ray per pixel) on the same triangles and camera, alpha-tested leaf cards honoured,
// for three views at 1920x1080 (benchmark argument `view`):
//   view 0: the synthetic stress forest of bench/forest_scene.hpp (1.08 M triangles, render.lod = false);
//   view 1: the product's default forest view of bench/default_view.hpp (default world, middle
//           autopilot pose, LODs on: Silva selects them; the peers are given the instances Silva
//           draws at the LODs it drew, so their culling and LOD work is done for them);
//   view 2: the same view at full detail (render.lod = false; the peers get every instance Silva
//           draws, at LOD 0).
// Every peer produces per-pixel depth + instance + triangle; after timing, its last frame is
// compared with Silva's and the run fails (error in the report) when fewer than 99% of the pixels
// have the same instance or fewer than 99% of the pixels both hit have depth within 0.1%.
// Setup (BVH build, context + upload) is timed apart from the warm per-frame time.
#include <benchmark/benchmark.h>

#include <memory>
#include <stdexcept>
#include <string>

#include <tbb/task_arena.h>

#include "bench/bench_views.hpp"
#include "bench/default_view.hpp"
#include "core/stopwatch.hpp"
#include "render/renderer.hpp"
#ifdef SILVA_PEER_EMBREE
#include "bench/peer_embree.hpp"
#endif
#ifdef SILVA_PEER_LLVMPIPE
#include "bench/peer_llvmpipe.hpp"
#endif

namespace {

using namespace silva;
using namespace silva::bench;

/// Relative depth tolerance of the cross-check.
constexpr double kDepthTolerance = 1e-3;
/// Smallest fraction of agreeing pixels the cross-check accepts (instance; depth of common hits).
constexpr double kMinAgreement = 0.99;

/// Work counts and times every benchmark reports.
void report(benchmark::State& state, const BenchView& v, double setup_ms, double cold_ms) {
  state.counters["triangles"] = double(v.triangles);
  state.counters["pixels"] = double(v.peers.camera->width) * double(v.peers.camera->height);
  state.counters["setup_ms"] = setup_ms;
  state.counters["cold_ms"] = cold_ms;
  state.counters["ms_per_frame"] = benchmark::Counter(1e-3, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

#if defined(SILVA_PEER_EMBREE) || defined(SILVA_PEER_LLVMPIPE)
/// Silva's visibility of the peers' scene of view 1 (`lod`) or 2, drawn with render.lod = false,
/// after checking that it is Silva's own frame of the full scene with the instances renumbered.
PeerFrame default_view_reference(bool lod) {
  const DefaultView& v = default_view();
  const FrozenView& f = lod ? v.drawn : v.full_detail;
  render::Renderer r;
  render::RenderOptions frozen;
  frozen.lod = false;
  render::RenderOptions own = frozen;
  own.lod = lod;
  PeerFrame full = from_visibility(r.render_visibility(v.frame.scene, v.camera, own));
  PeerFrame drawn = from_visibility(r.render_visibility(f.scene, v.camera, frozen));
  for (size_t i = 0; i < drawn.instance.size(); ++i) {
    const uint32_t inst = drawn.instance[i];
    const uint32_t renumbered = inst == render::kNoInstance ? inst : f.from[inst];
    if (renumbered != full.instance[i] || drawn.triangle[i] != full.triangle[i] || drawn.depth[i] != full.depth[i])
      throw std::runtime_error("default view: the frozen scene does not reproduce Silva's frame at pixel " +
                               std::to_string(i));
  }
  return drawn;
}

/// Silva's visibility of a view's peer scene (identical for any thread count), computed once per view.
const PeerFrame& silva_reference(int64_t view) {
  static const PeerFrame forest = [] {
    render::Renderer r;
    const BenchView v = bench_view(0);
    return from_visibility(r.render_visibility(*v.silva_scene, *v.peers.camera, v.options()));
  }();
  if (view == 0) return forest;
  if (view == 1) {
    static const PeerFrame world = default_view_reference(true);
    return world;
  }
  static const PeerFrame full_detail = default_view_reference(false);
  return full_detail;
}

/// Compares a peer's frame with Silva's; reports the agreement and fails the run below the bar.
void cross_check(benchmark::State& state, const PeerFrame& peer, const char* name) {
  const Agreement a = compare(peer, silva_reference(state.range(0)), kDepthTolerance);
  state.counters["agree_instance"] = a.instance;
  state.counters["agree_triangle"] = a.triangle;
  state.counters["agree_depth"] = a.depth;
  if (a.instance < kMinAgreement || a.depth < kMinAgreement)
    state.SkipWithError((std::string(name) + " disagrees with Silva: same instance " + std::to_string(a.instance) +
                         ", depth within 0.1% " + std::to_string(a.depth) + " (need >= 0.99 each)")
                            .c_str());
}
#endif

/// Silva: visibility pass in a task_arena of state.range(1) threads (setup: none; cold = first
/// frame); also reports its own work counts.
void BM_Silva(benchmark::State& state) {
  const BenchView v = bench_view(state.range(0));
  tbb::task_arena arena(int(state.range(1)));
  render::Renderer renderer;
  const render::RenderOptions opt = v.options();
  render::RenderStats stats;
  const auto frame = [&] { arena.execute([&] { renderer.render_visibility(*v.silva_scene, *v.peers.camera, opt, &stats); }); };
  const auto t0 = SteadyClock::now();
  frame();
  const double cold_ms = 1000 * seconds_since(t0);
  for (auto _ : state) frame();
  report(state, v, 0.0, cold_ms);
  state.counters["tri_submitted"] = double(stats.triangles_submitted);
  state.counters["tri_after_cull"] = double(stats.triangles_after_cull);
  state.counters["tri_rasterised"] = double(stats.triangles_rasterised);
}

/// llvmpipe: one frame = clear, draws, readback when `readback`, glFinish. 1 thread runs
/// LP_NUM_THREADS=0 (everything on the calling thread), 2 threads LP_NUM_THREADS=2.
void llvmpipe(benchmark::State& state, [[maybe_unused]] bool readback) {
#ifdef SILVA_PEER_LLVMPIPE
  const BenchView v = bench_view(state.range(0));
  const int lp_threads = state.range(1) == 1 ? 0 : int(state.range(1));
  LlvmpipePeer peer(v.peers, lp_threads);
  const auto t0 = SteadyClock::now();
  peer.render(readback);
  const double cold_ms = 1000 * seconds_since(t0);
  for (auto _ : state) peer.render(readback);
  report(state, v, peer.setup_ms(), cold_ms);
  state.counters["lp_num_threads"] = lp_threads;
  if (!readback) peer.render(true);
  cross_check(state, peer.frame(), "llvmpipe");
#else
  state.SkipWithError("built without the llvmpipe peer: EGL/OpenGL not found (Debian: libegl-dev libgl-dev "
                      "libgl1-mesa-dri libegl-mesa0)");
  for (auto _ : state) {
  }
#endif
}

void BM_Llvmpipe(benchmark::State& state) { llvmpipe(state, true); }
void BM_LlvmpipeNoReadback(benchmark::State& state) { llvmpipe(state, false); }

/// Embree: BVH build (setup) and rtcIntersect16 over 4x4 pixel packets, both in a task_arena of
/// state.range(1) threads.
void BM_Embree(benchmark::State& state) {
#ifdef SILVA_PEER_EMBREE
  const BenchView v = bench_view(state.range(0));
  tbb::task_arena arena(int(state.range(1)));
  std::unique_ptr<EmbreePeer> peer;
  arena.execute([&] { peer = std::make_unique<EmbreePeer>(v.peers); });
  PeerFrame out;
  const auto frame = [&] { arena.execute([&] { peer->render(out); }); };
  const auto t0 = SteadyClock::now();
  frame();
  const double cold_ms = 1000 * seconds_since(t0);
  for (auto _ : state) frame();
  report(state, v, peer->setup_ms(), cold_ms);
  cross_check(state, out, "Embree");
#else
  state.SkipWithError("built without the Embree peer: Embree 3 not found (Debian: libembree-dev)");
  for (auto _ : state) {
  }
#endif
}

}  // namespace

BENCHMARK(BM_Silva)->Apply(bench::views_and_threads);
BENCHMARK(BM_Llvmpipe)->Apply(bench::views_and_threads);
BENCHMARK(BM_LlvmpipeNoReadback)->Apply(bench::views_and_threads);
BENCHMARK(BM_Embree)->Apply(bench::views_and_threads);
