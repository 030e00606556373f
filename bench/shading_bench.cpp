// Shading benchmarks: shade_rgb at 1920x1080 on a synthetic G-buffer (ground plane, trunk
// columns, a foliage band, sky), 1 and 2 threads, plus the cost of its AO and sensor-noise draws.
#include <benchmark/benchmark.h>

#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "render/frame_lighting.hpp"
#include "render/post.hpp"
#include "render/shade.hpp"
#include "render/shade_ao.hpp"

namespace {

using namespace silva;
using namespace silva::render;

constexpr int kWidth = 1920, kHeight = 1080;

/// Camera 1.5 m above the origin looking along +X, 5 degrees down.
Camera bench_camera() {
  Camera cam = Camera::from_fov(kWidth, kHeight, 90, 0.05, 150);
  cam.camera_to_world = pose_from_angles(Vec3d(0, 0, 1.5), 0, -5, 0);
  return cam;
}

/// Ground plane z = 0 (ground/trail materials) with vertical trunk columns every 97 px and a
/// foliage band across the upper third; the rest is sky.
GBuffer bench_gbuffer(const Camera& cam) {
  GBuffer g;
  g.resize(cam.width, cam.height);
  const Vec3d o = cam.position();
  for (int v = 0; v < cam.height; ++v) {
    for (int u = 0; u < cam.width; ++u) {
      const size_t i = size_t(v) * size_t(cam.width) + size_t(u);
      const Vec3d d = cam.ray_direction(u, v);
      const bool trunk = u % 97 < 9, canopy = v < cam.height / 3 && (u / 61 + v / 47) % 3 != 0;
      if (!trunk && !canopy && d.z() >= 0) continue;
      const double t = trunk ? 8.0 + (u / 97) % 5 : canopy ? 12.0 : -o.z() / d.z();
      if (t >= cam.far) continue;
      const Vec3d p = o + t * d;
      g.depth[i] = float(t);
      g.position[i] = p.cast<float>();
      g.normal[i] = trunk || canopy ? Vec3f(-1, 0, 0) : Vec3f(0, 0, 1);
      g.material[i] = trunk    ? Material::BarkConifer
                      : canopy ? Material::Needles
                      : std::abs(p.y()) < 1.35 ? Material::Trail
                                               : Material::Ground;
      // As the terrain carries it: signed distance to the trail's edge, arc length along it.
      g.uv[i] = Vec2f(float(std::abs(p.y()) - 0.75), float(p.x()));
      g.variation[i] = uint32_t(u / 97);
    }
  }
  return g;
}

/// 2048^2 shadow map straight down over 200 m, all ground at depth 0 (every lookup does PCF).
ShadowMap bench_shadow() {
  ShadowMap map;
  map.width = map.height = 2048;
  map.texel_size = 200.0 / 2048;
  map.origin_x = map.origin_y = -100;
  map.world_to_light << 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1;
  map.depth.assign(size_t(2048) * 2048, 0.0f);
  return map;
}

/// Fixture data shared by the benchmarks (built once).
struct Scene {
  Camera camera = bench_camera();
  GBuffer gbuffer = bench_gbuffer(camera);
  ShadowMap shadow = bench_shadow();
};

const Scene& scene() {
  static const Scene s;
  return s;
}

void BM_ShadeRgb(benchmark::State& state) {
  const Scene& s = scene();
  LightingPreset preset = preset_day();
  preset.sun_elevation_deg = 70;
  const CameraModel model = camera_model(CameraConfig{}, s.camera);
  std::vector<uint8_t> rgb;
  tbb::task_arena arena(int(state.range(0)));
  for (auto _ : state) {
    arena.execute([&] { shade_rgb({s.gbuffer, s.camera, preset, &s.shadow, 1, "random", 0, model}, rgb); });
    benchmark::DoNotOptimize(rgb.data());
  }
  state.counters["threads"] = double(state.range(0));
  state.counters["pixels"] = double(s.gbuffer.size());
  state.counters["Mpixels/s"] =
      benchmark::Counter(double(s.gbuffer.size()) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_ShadeRgb)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

/// The camera models BM_ShadeRgbCamera compares: 0 none, 1 the default, 2-4 the default plus
/// chromatic aberration, depth of field or motion blur (0.014 m forward and 0.1 degree of yaw).
CameraModel bench_model(int64_t which, const Camera& cam) {
  CameraModel m = camera_model(CameraConfig{}, cam);
  if (which == 0) return {};
  if (which == 2) m.chromatic_aberration = 0.002;
  if (which == 3) m.depth_of_field = DepthOfField{2.0, 3.0, 5.65};
  if (which == 4)
    m.motion = ExposureMotion{0.01, pose_from_angles(cam.position() - Vec3d(0.007, 0, 0), -0.05, -5, 0),
                              pose_from_angles(cam.position() + Vec3d(0.007, 0, 0), 0.05, -5, 0)};
  return m;
}

/// shade_rgb on 2 threads with camera model `state.range(0)` (bench_model); run with
/// --benchmark_enable_random_interleaving to compare them.
void BM_ShadeRgbCamera(benchmark::State& state) {
  const Scene& s = scene();
  LightingPreset preset = preset_day();
  preset.sun_elevation_deg = 70;
  const CameraModel model = bench_model(state.range(0), s.camera);
  std::vector<uint8_t> rgb;
  tbb::task_arena arena(2);
  for (auto _ : state) {
    arena.execute([&] { shade_rgb({s.gbuffer, s.camera, preset, &s.shadow, 1, "random", 0, model}, rgb); });
    benchmark::DoNotOptimize(rgb.data());
  }
  state.counters["model"] = double(state.range(0));
}
BENCHMARK(BM_ShadeRgbCamera)->DenseRange(0, 4)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);

/// shade_rgb on 2 threads with the default camera model and the exposure `state.range(0)`: 0 the preset's,
/// 1 automatic (the frame is kept whole and metered), 2 the preset's with a randomised white balance.
void BM_ShadeRgbExposure(benchmark::State& state) {
  const Scene& s = scene();
  LightingPreset preset = preset_day();
  preset.sun_elevation_deg = 70;
  const CameraModel model = camera_model(CameraConfig{}, s.camera);
  const bool automatic = state.range(0) == 1;
  const Vec3f white_balance = state.range(0) == 2 ? white_balance_gains(5600.0f) : Vec3f::Ones();
  std::vector<uint8_t> rgb;
  tbb::task_arena arena(2);
  for (auto _ : state) {
    arena.execute([&] {
      shade_rgb({s.gbuffer, s.camera, preset, &s.shadow, 1, "random", 0, model, automatic, 0.0f, white_balance}, rgb);
    });
    benchmark::DoNotOptimize(rgb.data());
  }
  state.counters["exposure"] = double(state.range(0));
}
BENCHMARK(BM_ShadeRgbExposure)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);

/// One frame's randomised lighting draw (render/frame_lighting.hpp), as every frame of a randomised run makes.
void BM_FrameLightingDraw(benchmark::State& state) {
  RunLighting run;
  run.randomize.enabled = true;
  for (const std::string& name : run.randomize.weathers) run.weather_choices.push_back(builtin_weathers().at(name));
  uint64_t frame = 0;
  for (auto _ : state) benchmark::DoNotOptimize(frame_lighting(run, 1, "random", frame++));
}
BENCHMARK(BM_FrameLightingDraw);

void BM_ScreenSpaceAo(benchmark::State& state) {
  const Scene& s = scene();
  for (auto _ : state) {
    float sum = 0;
    for (int v = 0; v < kHeight; ++v)
      for (int u = 0; u < kWidth; ++u)
        if (s.gbuffer.depth[size_t(v) * kWidth + size_t(u)] > 0) sum += screen_space_ao(s.gbuffer, s.camera, u, v);
    benchmark::DoNotOptimize(sum);
  }
  state.counters["pixels"] = double(s.gbuffer.size());
}
BENCHMARK(BM_ScreenSpaceAo)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SensorNormals(benchmark::State& state) {
  const uint64_t key = noise_key("random", 0);
  for (auto _ : state) {
    Vec3f sum = Vec3f::Zero();
    for (size_t i = 0; i < size_t(kWidth) * kHeight; ++i) sum += sensor_normals(1, key, i);
    benchmark::DoNotOptimize(sum);
  }
  state.counters["pixels"] = double(kWidth) * kHeight;
}
BENCHMARK(BM_SensorNormals)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
