// Encoder benchmarks (bench/README.md "Encoders"): every output of one 1920x1080 capture set on
// one thread, the whole set in parallel on 1 and 2 threads, Silva's PNG writer against OpenCV
// imencode (level 1) in the same run, and the filter x level sweep behind PngOptions' defaults.
#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <ctime>
#include <cmath>
#include <opencv2/imgcodecs.hpp>

#include "core/instance_id.hpp"
#include "core/rng.hpp"
#include "io/capture_set.hpp"
#include "io/label_planes.hpp"
#include "io/exr_writer.hpp"
#include "io/label_images.hpp"
#include "io/png_writer.hpp"
#include "render/gbuffer.hpp"

namespace {

using namespace silva;
constexpr int kW = 1920, kH = 1080;
constexpr uint64_t kSeed = 20240601;

/// A forest-like G-buffer: sky above the horizon, ground with a trail, 60 trees, grass patches.
render::GBuffer make_gbuffer() {
  render::GBuffer g;
  g.resize(kW, kH);
  const double f = 960.0, horizon = 540.0;
  for (int y = int(horizon); y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const size_t i = size_t(y) * kW + x;
      const double z = 1.5 * f / (y + 0.5 - horizon);
      if (z > 150.0) continue;
      g.depth[i] = float(z);
      const double lateral = (x + 0.5 - 960.0) / f * z;
      const bool grass = std::sin(0.37 * lateral) * std::cos(0.21 * z) > 0.4;
      g.role[i] = std::abs(lateral) < 0.75 ? Role::Trail : grass ? Role::GroundVegetation : Role::Ground;
      g.normal[i] = Vec3f(0.05f * float(std::sin(lateral)), 0.05f * float(std::cos(z)), 1.0f).normalized();
    }
  Rng rng(kSeed, 0, Purpose::Test);
  for (uint32_t t = 0; t < 60; ++t) {
    const double z = 3.0 + 60.0 * rng.uniform_double();
    const int cx = int(rng.below(kW)), half = std::max(2, int(0.25 * 960.0 / z));
    const int ground_y = std::min(kH - 1, int(horizon + 1.5 * 960.0 / z));
    const int top = std::max(0, int(horizon - 12.0 * 960.0 / z));
    const uint32_t id = pack_instance_id(ChunkCoord{int32_t(t % 5), int32_t(t / 5)}, t);
    const Role trunk = t % 7 == 0 ? Role::DeadTree : Role::TreeTrunk;
    for (int y = top; y <= ground_y; ++y) {
      const bool canopy = trunk == Role::TreeTrunk && y < (top + ground_y) / 2;
      const int w = canopy ? 6 * half : half;
      for (int x = std::max(0, cx - w); x < std::min(kW, cx + w); ++x) {
        const size_t i = size_t(y) * kW + x;
        if (g.depth[i] > 0 && g.depth[i] < z) continue;
        g.depth[i] = float(z);
        g.role[i] = canopy ? Role::TreeCanopy : trunk;
        g.instance_id[i] = canopy ? 0 : id;
        g.normal[i] = Vec3f(float(x - cx), -float(w), 0.1f).normalized();
      }
    }
  }
  return g;
}

/// Shaded colour by class with noise (sigma of 4 levels), R, G, B interleaved.
std::vector<uint8_t> make_rgb(const render::GBuffer& g) {
  const Ontology o = default_ontology();
  std::vector<uint8_t> rgb(g.size() * 3);
  for (size_t i = 0; i < g.size(); ++i) {
    Rng grain(kSeed, i, Purpose::SensorNoise);
    const auto& c = o.color(g.role[i]);
    const float shade = g.depth[i] > 0 ? 0.6f + 0.4f * std::abs(g.normal[i].z()) : 1.0f;
    for (int a = 0; a < 3; ++a) {
      const float base = g.depth[i] > 0 ? 40.0f + 0.6f * c[a] * shade : 150.0f + 0.05f * float(i / kW);
      rgb[3 * i + a] = uint8_t(std::clamp(base + 4.0f * grain.normal(), 0.0f, 255.0f));
    }
  }
  return rgb;
}

struct Fixture {
  render::GBuffer gbuffer = make_gbuffer();
  io::LabelPlanes g{gbuffer.width, gbuffer.height, gbuffer.depth, gbuffer.normal, gbuffer.role, gbuffer.instance_id};
  std::vector<uint8_t> rgb = make_rgb(gbuffer);
  Ontology ontology = default_ontology();
};
const Fixture& fixture() {
  static const Fixture f;
  return f;
}

/// Runs `encode` (returning total bytes) per iteration and reports the bytes written.
template <class F>
void run(benchmark::State& state, F encode) {
  fixture();  // build the inputs outside the timed loop
  size_t bytes = 0;
  for (auto _ : state) {
    bytes = encode();
    benchmark::DoNotOptimize(bytes);
  }
  state.counters["bytes"] = double(bytes);
  state.counters["pixels"] = double(kW) * kH;
}

void BM_Rgb(benchmark::State& s) { run(s, [] { return io::encode_png_rgb8(fixture().rgb, kW, kH).size(); }); }
void BM_Semantic(benchmark::State& s) {
  run(s, [] { return io::encode_png_grey8(io::semantic_image(fixture().g, fixture().ontology), kW, kH).size(); });
}
void BM_SemanticColor(benchmark::State& s) {
  run(s, [] { return io::encode_png_rgb8(io::semantic_color_image(fixture().g, fixture().ontology), kW, kH).size(); });
}
void BM_Instance(benchmark::State& s) {
  run(s, [] {
    const io::InstanceImage inst = io::instance_image(fixture().g, fixture().ontology);
    return io::encode_png_grey16(inst.pixels, kW, kH).size() + io::instance_table_json(inst.entries).size();
  });
}
void BM_Depth(benchmark::State& s) {
  run(s, [] { return io::encode_png_grey16(io::depth_mm_image(fixture().g), kW, kH).size(); });
}
void BM_DepthExr(benchmark::State& s) { run(s, [] { return io::encode_exr_y(fixture().g.depth, kW, kH).size(); }); }
void BM_DepthPreview(benchmark::State& s) {
  run(s, [] { return io::encode_png_grey8(io::depth_preview_image(fixture().g), kW, kH).size(); });
}
void BM_Normal(benchmark::State& s) {
  run(s, [] { return io::encode_png_rgb8(io::normal_image(fixture().g), kW, kH).size(); });
}

/// The whole set (all eight outputs) through encode_capture_set on a task_arena of range(0) threads.
void BM_WholeSet(benchmark::State& s) {
  tbb::task_arena arena(int(s.range(0)));
  run(s, [&] {
    size_t total = 0;
    arena.execute([&] {
      for (const auto& f : io::encode_capture_set(fixture().g, fixture().rgb, fixture().ontology,
                                                  io::OutputSelection::all(), 0, false))
        total += f.bytes.size();
    });
    return total;
  });
}

/// CPU seconds used by the calling thread (robust to other load on the machine).
double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

/// Silva's RGB PNG (default options) against OpenCV imencode at level 1 in the same loop, both on
/// this thread; times are thread CPU time, the ratio is OpenCV / Silva.
void BM_RgbSilvaVsOpenCv(benchmark::State& s) {
  cv::Mat bgr(kH, kW, CV_8UC3);
  const auto& rgb = fixture().rgb;
  for (size_t i = 0; i < size_t(kW) * kH; ++i)
    for (int a = 0; a < 3; ++a) bgr.data[3 * i + a] = rgb[3 * i + 2 - a];
  double silva_s = 0, opencv_s = 0;
  size_t silva_bytes = 0;
  std::vector<uint8_t> cv_bytes;
  for (auto _ : s) {
    const double t0 = thread_cpu_seconds();
    silva_bytes = io::encode_png_rgb8(rgb, kW, kH).size();
    const double t1 = thread_cpu_seconds();
    cv::imencode(".png", bgr, cv_bytes, {cv::IMWRITE_PNG_COMPRESSION, 1});
    const double t2 = thread_cpu_seconds();
    silva_s += t1 - t0;
    opencv_s += t2 - t1;
  }
  const double n = double(s.iterations());
  s.counters["silva_cpu_ms"] = 1e3 * silva_s / n;
  s.counters["opencv_cpu_ms"] = 1e3 * opencv_s / n;
  s.counters["opencv_over_silva"] = opencv_s / silva_s;
  s.counters["silva_bytes"] = double(silva_bytes);
  s.counters["opencv_bytes"] = double(cv_bytes.size());
}

/// Filter (0..4) x level sweep on the RGB, depth and semantic images: range(0) image, range(1)
/// filter, range(2) level.
void BM_PngSweep(benchmark::State& s) {
  const io::PngOptions opt{io::PngFilter(s.range(1)), int(s.range(2))};
  static const std::vector<uint16_t> depth = io::depth_mm_image(fixture().g);
  static const std::vector<uint8_t> sem = io::semantic_image(fixture().g, fixture().ontology);
  switch (s.range(0)) {
    case 0: run(s, [&] { return io::encode_png_rgb8(fixture().rgb, kW, kH, opt).size(); }); break;
    case 1: run(s, [&] { return io::encode_png_grey16(depth, kW, kH, opt).size(); }); break;
    default: run(s, [&] { return io::encode_png_grey8(sem, kW, kH, opt).size(); }); break;
  }
}

/// EXR ZIP level sweep: range(0) = libdeflate level.
void BM_ExrLevel(benchmark::State& s) {
  run(s, [&] { return io::encode_exr_y(fixture().g.depth, kW, kH, int(s.range(0))).size(); });
}

void sweep_args(benchmark::internal::Benchmark* b) {
  b->ArgNames({"image", "filter", "level"});
  for (int image : {0, 1, 2})
    for (int filter : {0, 1, 2, 4})
      for (int level : {1, 3, 6}) b->Args({image, filter, level});
}

}  // namespace

BENCHMARK(BM_Rgb)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Semantic)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SemanticColor)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Instance)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Depth)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DepthExr)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DepthPreview)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Normal)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WholeSet)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RgbSilvaVsOpenCv)->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK(BM_PngSweep)->Apply(sweep_args)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_ExrLevel)->Arg(1)->Arg(3)->Arg(6)->Unit(benchmark::kMillisecond)->Iterations(3);
