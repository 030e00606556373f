// `silva view`'s frame path (pipeline/schedule/view_world.hpp): the schedule's Stream .. Render for a
// free camera, the view's shading or label colours, and JPEG encoding, on the default world (default
// config, seed 1234567890), at the page's 960x540 and at the 480x270 it asks for while moving
// (mode 0 = RGB, 1 = semantic). Moving: each frame walks 0.3 m along the trail (3 m/s, the page's walk
// speed, at 10 frames/s) with the yaw swinging, so chunks stream in as they do on the page. First
// frame: loading the run inputs plus the first frame, as `silva view` does before printing its URL
// (cold: the first iteration; the chunk cache is empty each time).
#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <memory>

#include "pipeline/schedule/view_world.hpp"
#include "pipeline/config/config_loader.hpp"

namespace {

using namespace silva;

/// Seed of every benchmark world.
constexpr const char* kSeed = "1234567890";
/// The page's view size; while moving the page asks for half of it each way (width 480).
constexpr int kWidth = 960, kHeight = 540;

/// The default config with the benchmark seed.
pipeline::LoadedConfig bench_config() {
  pipeline::ConfigSources sources;
  sources.seed = kSeed;
  return pipeline::load_config(sources);
}

/// The pose `i` frames into the walk: along the trail, yaw swinging +-30 degrees about it.
pipeline::ViewPose walk_pose(const nlohmann::json& trail, int i) {
  const double s = std::fmod(0.3 * i, double(trail.size() - 1));
  const nlohmann::json& p = trail[size_t(s)];
  pipeline::ViewPose pose;
  pose.walk = true;
  pose.position = Vec3d(p[0].get<double>(), p[1].get<double>(), 0);
  pose.yaw_deg = p[3].get<double>() + 30 * std::sin(0.05 * i);
  return pose;
}

void BM_ViewFrameMoving(benchmark::State& state) {
  const int threads = int(state.range(0));
  const pipeline::ViewMode mode = pipeline::ViewMode(state.range(1));
  const int width = int(state.range(2)), height = width * kHeight / kWidth;
  tbb::task_arena arena(threads);
  arena.execute([&] {
    pipeline::ViewWorld view(bench_config());
    const nlohmann::json trail = view.trail(1.0);
    int i = 0;
    view.render(walk_pose(trail, i++), mode, width, height);  // warm: the start's chunks
    double schedule = 0, raster = 0, shade = 0, encode = 0;
    for (auto _ : state) {
      const pipeline::ViewFrame f = view.render(walk_pose(trail, i++), mode, width, height);
      benchmark::DoNotOptimize(f.jpeg.data());
      schedule += f.schedule_ms, raster += f.raster_ms, shade += f.shade_ms, encode += f.encode_ms;
    }
    const double n = double(state.iterations());
    state.counters["frames_per_s"] = benchmark::Counter(n, benchmark::Counter::kIsRate);
    state.counters["schedule_ms"] = schedule / n;  // streaming, scene, visibility and shadow map
    state.counters["raster_ms"] = raster / n;      // of which the visibility pass and the shadow map
    state.counters["shade_ms"] = shade / n;
    state.counters["encode_ms"] = encode / n;
    state.counters["threads"] = threads;
    state.counters["pixels"] = width * height;
  });
}
BENCHMARK(BM_ViewFrameMoving)
    ->ArgsProduct({{1, 2}, {int(pipeline::ViewMode::Rgb), int(pipeline::ViewMode::Semantic)}, {kWidth, kWidth / 2}})
    ->ArgNames({"threads", "mode", "width"})
    ->Iterations(40)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_ViewFirstFrame(benchmark::State& state) {
  tbb::task_arena arena(int(state.range(0)));
  arena.execute([&] {
    for (auto _ : state) {
      pipeline::ViewWorld view(bench_config());
      const pipeline::ViewFrame f = view.render(view.start_pose(), pipeline::ViewMode::Rgb, kWidth, kHeight);
      benchmark::DoNotOptimize(f.jpeg.data());
    }
  });
}
BENCHMARK(BM_ViewFirstFrame)->Arg(2)->ArgName("threads")->Iterations(3)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
