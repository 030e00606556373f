// Peers benchmark: Silva's visibility pass against Mesa llvmpipe (OpenGL on the CPU) and Embree 3
// (one primary ray per pixel) on the same triangles and camera: the forest of
// bench/forest_scene.hpp at 1920x1080, render.lod = false, alpha-tested leaf cards honoured.
// Every peer produces per-pixel depth + instance + triangle; after timing, its last frame is
// compared with Silva's and the run fails (error in the report) when fewer than 99% of the pixels
// have the same instance or fewer than 99% of the pixels both hit have depth within 0.1%.
// Setup (BVH build, context + upload) is timed apart from the warm per-frame time.
#include <benchmark/benchmark.h>

#include <chrono>
#include <memory>
#include <string>

#include <tbb/task_arena.h>

#include "bench/forest_scene.hpp"
#include "bench/peer_frame.hpp"
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

/// Milliseconds since `t0`.
double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

/// Work counts and times every benchmark reports.
void report(benchmark::State& state, double setup_ms, double cold_ms) {
  const ForestScene& w = forest_scene();
  state.counters["triangles"] = double(w.triangle_count());
  state.counters["pixels"] = double(w.camera.width) * double(w.camera.height);
  state.counters["setup_ms"] = setup_ms;
  state.counters["cold_ms"] = cold_ms;
  state.counters["ms_per_frame"] = benchmark::Counter(1e-3, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

#if defined(SILVA_PEER_EMBREE) || defined(SILVA_PEER_LLVMPIPE)
/// Silva's visibility of the scene (identical for any thread count), computed once.
const PeerFrame& silva_reference() {
  static const PeerFrame f = [] {
    render::Renderer r;
    render::RenderOptions opt;
    opt.lod = false;
    return from_visibility(r.render_visibility(forest_scene().scene, forest_scene().camera, opt));
  }();
  return f;
}

/// Compares a peer's frame with Silva's; reports the agreement and fails the run below the bar.
void cross_check(benchmark::State& state, const PeerFrame& peer, const char* name) {
  const Agreement a = compare(peer, silva_reference(), kDepthTolerance);
  state.counters["agree_instance"] = a.instance;
  state.counters["agree_triangle"] = a.triangle;
  state.counters["agree_depth"] = a.depth;
  if (a.instance < kMinAgreement || a.depth < kMinAgreement)
    state.SkipWithError((std::string(name) + " disagrees with Silva: same instance " + std::to_string(a.instance) +
                         ", depth within 0.1% " + std::to_string(a.depth) + " (need >= 0.99 each)")
                            .c_str());
}
#endif

/// Silva: visibility pass in a task_arena of state.range(0) threads (setup: none; cold = first frame).
void BM_Silva(benchmark::State& state) {
  const ForestScene& w = forest_scene();
  tbb::task_arena arena(int(state.range(0)));
  render::Renderer renderer;
  render::RenderOptions opt;
  opt.lod = false;
  const auto frame = [&] { arena.execute([&] { renderer.render_visibility(w.scene, w.camera, opt); }); };
  const auto t0 = std::chrono::steady_clock::now();
  frame();
  const double cold_ms = ms_since(t0);
  for (auto _ : state) frame();
  report(state, 0.0, cold_ms);
}

/// llvmpipe: one frame = clear, draws, readback when `readback`, glFinish. 1 thread runs
/// LP_NUM_THREADS=0 (everything on the calling thread), 2 threads LP_NUM_THREADS=2.
void llvmpipe(benchmark::State& state, [[maybe_unused]] bool readback) {
#ifdef SILVA_PEER_LLVMPIPE
  const int lp_threads = state.range(0) == 1 ? 0 : int(state.range(0));
  LlvmpipePeer peer(forest_scene(), lp_threads);
  const auto t0 = std::chrono::steady_clock::now();
  peer.render(readback);
  const double cold_ms = ms_since(t0);
  for (auto _ : state) peer.render(readback);
  report(state, peer.setup_ms(), cold_ms);
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
/// state.range(0) threads.
void BM_Embree(benchmark::State& state) {
#ifdef SILVA_PEER_EMBREE
  tbb::task_arena arena(int(state.range(0)));
  std::unique_ptr<EmbreePeer> peer;
  arena.execute([&] { peer = std::make_unique<EmbreePeer>(forest_scene()); });
  PeerFrame out;
  const auto frame = [&] { arena.execute([&] { peer->render(out); }); };
  const auto t0 = std::chrono::steady_clock::now();
  frame();
  const double cold_ms = ms_since(t0);
  for (auto _ : state) frame();
  report(state, peer->setup_ms(), cold_ms);
  cross_check(state, out, "Embree");
#else
  state.SkipWithError("built without the Embree peer: Embree 3 not found (Debian: libembree-dev)");
  for (auto _ : state) {
  }
#endif
}

}  // namespace

BENCHMARK(BM_Silva)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(BM_Llvmpipe)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(BM_LlvmpipeNoReadback)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(BM_Embree)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
