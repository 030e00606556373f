#include "systems/capture_pipeline.hpp"

#include <tbb/parallel_pipeline.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <mutex>
#include <system_error>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/camera_json.hpp"
#include "io/capture_set.hpp"
#include "render/edge_aa.hpp"
#include "render/renderer.hpp"
#include "render/shade.hpp"
#include "systems/chunk_regions.hpp"
#include "systems/terrain.hpp"

namespace silva::world {

namespace fs = std::filesystem;

namespace {
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// One frame travelling through the pipeline.
struct FrameWork {
  const PlannedFrame* frame = nullptr;
  RenderedFrame rendered;
  std::vector<uint8_t> rgb_scratch;  ///< Edge-filtered RGB before it is swapped into `rendered.rgb`.
  render::ShadowMap shadow;
  io::EncodedSet files;
  double stream_s = 0, prepare_s = 0, render_s = 0, shadow_s = 0, shade_s = 0, encode_s = 0;
  uint64_t triangles_submitted = 0, triangles_rasterised = 0;

  /// Starts frame `f`, keeping the buffers (G-buffer, RGB, shadow map) for reuse.
  void start(const PlannedFrame& f) {
    frame = &f;
    files.clear();
    stream_s = prepare_s = render_s = shadow_s = shade_s = encode_s = 0;
    triangles_submitted = triangles_rasterised = 0;
  }
};

/// Recycles FrameWork objects, so each in-flight frame's big buffers are allocated once per run
/// rather than once per frame (page faults and clears were several percent of a frame).
class FramePool {
 public:
  /// A frame slot (recycled when one is free); it goes back to the pool when the last owner drops it.
  std::shared_ptr<FrameWork> take() {
    std::unique_ptr<FrameWork> w;
    {
      const std::lock_guard lock(mutex_);
      if (!free_.empty()) {
        w = std::move(free_.back());
        free_.pop_back();
      }
    }
    if (!w) w = std::make_unique<FrameWork>();
    return std::shared_ptr<FrameWork>(w.release(), [this](FrameWork* p) {
      const std::lock_guard lock(mutex_);
      free_.emplace_back(p);
    });
  }

 private:
  std::mutex mutex_;
  std::vector<std::unique_ptr<FrameWork>> free_;
};

/// The chunks a view needs: those meeting its frustum, plus a disc around the camera whose
/// objects may cast shadows into the view.
std::vector<ChunkCoord> chunks_for_view(const WorldContext& ctx, const Camera& camera) {
  std::vector<ChunkCoord> coords = chunks_in_view(camera, ctx.chunk_size());
  const Vec3d p = camera.position();
  for (ChunkCoord c : chunks_in_disc(p.x(), p.y(), 0.25 * kShadowExtent, ctx.chunk_size()))
    if (std::find(coords.begin(), coords.end(), c) == coords.end()) coords.push_back(c);
  std::sort(coords.begin(), coords.end());
  return coords;
}

/// Streams, prepares and renders one frame (G-buffer + shadow map); timings into `work`.
void render_into(const CaptureJob& job, ChunkCache& cache, const SceneBuilder& builder, render::Renderer& renderer,
                 FrameWork& work) {
  const WorldContext& ctx = *job.world;
  const PlannedFrame& f = *work.frame;
  render::RenderOptions options;
  options.lod = ctx.config.render.lod;

  auto t = Clock::now();
  auto chunks = cache.require(ctx, chunks_for_view(ctx, f.camera));
  work.stream_s = seconds_since(t);

  t = Clock::now();
  const FrameScene scene = builder.build(std::move(chunks));
  work.prepare_s = seconds_since(t);

  t = Clock::now();
  render::RenderStats stats;
  renderer.render_gbuffer(scene.scene, f.camera, options, work.rendered.gbuffer, &stats);
  work.render_s = seconds_since(t);
  work.triangles_submitted = stats.triangles_submitted;
  work.triangles_rasterised = stats.triangles_rasterised;

  if (job.outputs.has(io::OutputType::Rgb)) {
    t = Clock::now();
    const Vec3f sun = render::sun_direction(job.preset);
    const ShadowPlan plan = plan_shadow(ctx, f.camera, sun.cast<double>());
    renderer.render_shadow_map(scene.scene, sun.cast<double>(), plan.region, plan.resolution, options, work.shadow);
    work.shadow_s = seconds_since(t);
  }
}

/// Shades RGB (when selected) from the rendered G-buffer and shadow map.
void shade_into(const CaptureJob& job, FrameWork& work) {
  if (!job.outputs.has(io::OutputType::Rgb)) return;
  const PlannedFrame& f = *work.frame;
  const auto t = Clock::now();
  const render::ShadeInputs in{work.rendered.gbuffer, f.camera, job.preset, &work.shadow,
                               uint64_t(job.world->config.seed), f.sequence, uint64_t(f.frame),
                               float(job.world->config.camera.film_grain)};
  render::shade_rgb(in, work.rendered.rgb);
  if (job.world->config.camera.antialias) {
    const render::GBuffer& g = work.rendered.gbuffer;
    render::smooth_edges(work.rendered.rgb, g.width, g.height, work.rgb_scratch);
    work.rendered.rgb.swap(work.rgb_scratch);
  }
  work.shade_s = seconds_since(t);
}

/// The camera record of a planned frame.
io::CameraRecord camera_record(const PlannedFrame& f) {
  io::CameraRecord r;
  r.frame = f.frame;
  r.sequence = f.sequence;
  r.perspective = f.aerial ? io::Perspective::Aerial : io::Perspective::Ground;
  r.camera = f.camera;
  r.yaw_deg = f.yaw_deg;
  r.pitch_deg = f.pitch_deg;
  r.roll_deg = f.roll_deg;
  r.trail_s = f.trail_s;
  return r;
}

/// Creates the output folders of every sequence the job writes.
void create_folders(const CaptureJob& job) {
  for (const PlannedFrame& f : job.frames) {
    const fs::path seq = job.run_dir / f.sequence;
    if (fs::exists(seq / "camera")) continue;
    std::vector<std::string> names = {"camera"};
    for (int t = 0; t < io::kOutputTypeCount; ++t)
      if (job.outputs.has(io::OutputType(t))) names.push_back(io::output_type_name(io::OutputType(t)));
    for (const auto& n : names) {
      std::error_code ec;
      fs::create_directories(seq / n, ec);
      if (ec) throw IoError("cannot create folder " + (seq / n).string() + ": " + ec.message());
    }
  }
}
}  // namespace

fs::path camera_file(const PlannedFrame& frame) {
  return fs::path(frame.sequence) / io::frame_file("camera", frame.frame, "json");
}

RenderedFrame render_frame(const CaptureJob& job, ChunkCache& cache, const PlannedFrame& frame) {
  render::Renderer renderer;
  const SceneBuilder builder(*job.world->library);
  FrameWork work;
  work.frame = &frame;
  render_into(job, cache, builder, renderer, work);
  shade_into(job, work);
  return std::move(work.rendered);
}

CaptureStats run_capture(const CaptureJob& job, ChunkCache& cache, const ProgressFn& progress) {
  CaptureStats stats;
  const auto t_run = Clock::now();
  create_folders(job);
  const size_t generated_before = cache.generated();
  render::Renderer renderer;
  const SceneBuilder builder(*job.world->library);
  FramePool pool;
  size_t next = 0;
  const int total = int(job.frames.size());

  auto render_stage = [&](tbb::flow_control& fc) -> std::shared_ptr<FrameWork> {
    if (next >= job.frames.size() || (job.stop && job.stop())) {
      stats.stopped = next < job.frames.size();
      fc.stop();
      return nullptr;
    }
    auto work = pool.take();
    work->start(job.frames[next++]);
    render_into(job, cache, builder, renderer, *work);
    return work;
  };
  auto encode_stage = [&](const std::shared_ptr<FrameWork>& work) {
    shade_into(job, *work);
    const auto t = Clock::now();
    work->files = io::encode_capture_set(work->rendered.gbuffer, work->rendered.rgb, job.ontology, job.outputs,
                                         work->frame->frame);
    work->encode_s = seconds_since(t);
    return work;
  };
  auto write_stage = [&](const std::shared_ptr<FrameWork>& work) {
    const auto t = Clock::now();
    const fs::path seq = job.run_dir / work->frame->sequence;
    for (const io::EncodedFile& file : work->files) {
      io::write_file_atomic(seq / file.relative_path, file.bytes);
      stats.bytes_written += file.bytes.size();
    }
    const std::string camera = io::camera_json(camera_record(*work->frame));
    io::write_file_atomic(job.run_dir / camera_file(*work->frame), camera);
    stats.bytes_written += camera.size();
    stats.write_s += seconds_since(t);
    stats.stream_s += work->stream_s;
    stats.prepare_s += work->prepare_s;
    stats.render_s += work->render_s;
    stats.shadow_s += work->shadow_s;
    stats.shade_s += work->shade_s;
    stats.encode_s += work->encode_s;
    stats.triangles_submitted += work->triangles_submitted;
    stats.triangles_rasterised += work->triangles_rasterised;
    ++stats.frames_written;
    if (progress) progress(stats.frames_written, total);
  };

  tbb::parallel_pipeline(
      kFramesInFlight,
      tbb::make_filter<void, std::shared_ptr<FrameWork>>(tbb::filter_mode::serial_in_order, render_stage) &
          tbb::make_filter<std::shared_ptr<FrameWork>, std::shared_ptr<FrameWork>>(tbb::filter_mode::parallel,
                                                                                   encode_stage) &
          tbb::make_filter<std::shared_ptr<FrameWork>, void>(tbb::filter_mode::serial_in_order, write_stage));
  stats.chunks_generated = cache.generated() - generated_before;
  stats.wall_s = seconds_since(t_run);
  return stats;
}

}  // namespace silva::world
