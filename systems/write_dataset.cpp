#include "systems/write_dataset.hpp"

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <utility>

#include "components/phase.hpp"
#include "components/world_source.hpp"
#include "core/error.hpp"
#include "core/stopwatch.hpp"
#include "io/atomic_file.hpp"
#include "io/camera_json.hpp"
#include "io/disparity.hpp"
#include "io/jpeg_writer.hpp"
#include "io/png_writer.hpp"
#include "io/label_planes.hpp"
#include "io/lidar_files.hpp"
#include "render/edge_aa.hpp"
#include "render/materials.hpp"
#include "render/shade.hpp"
#include "systems/render_views.hpp"
#include "world/world_context.hpp"

namespace silva::systems {

namespace fs = std::filesystem;

namespace {

/// The camera model of a planned frame: `[camera]`'s, with the frame's motion while the shutter is open.
CameraModel frame_camera_model(const Config& config, const world::PlannedFrame& f) {
  CameraModel model = camera_model(config.camera, f.camera);
  model.motion = f.exposure_motion;
  return model;
}

/// The lighting record of a frame: its drawn values and exposure, when randomised or auto-exposed.
std::optional<io::LightingRecord> lighting_record(const FrameWork& work, bool rgb) {
  const render::FrameLighting& l = work.lighting;
  if (!l.randomized && !l.auto_exposure) return std::nullopt;
  io::LightingRecord r;
  r.time_of_day = l.time_of_day;
  r.weather = l.weather;
  r.randomized = l.randomized;
  r.sun_elevation_deg = l.preset.sun_elevation_deg;
  r.sun_azimuth_deg = l.preset.sun_azimuth_deg;
  r.cloud_cover = l.preset.cloud_cover;
  r.fog_density_scale = l.fog_density_scale;
  r.white_balance_k = l.white_balance_k;
  r.exposure = l.auto_exposure ? "auto" : "preset";
  r.exposure_compensation_ev = l.exposure_compensation_ev;
  if (rgb) r.ev100 = work.ev100;
  return r;
}

/// The camera record of a planned frame (`stereo_baseline_m` > 0: one camera of a stereo pair).
io::CameraRecord camera_record(const Config& config, const world::PlannedFrame& f, double stereo_baseline_m) {
  io::CameraRecord r;
  r.frame = f.frame;
  r.sequence = f.sequence;
  r.perspective = f.aerial ? io::Perspective::Aerial : io::Perspective::Ground;
  r.camera = f.camera;
  r.yaw_deg = f.yaw_deg;
  r.pitch_deg = f.pitch_deg;
  r.roll_deg = f.roll_deg;
  r.trail_s = f.trail_s;
  r.model = frame_camera_model(config, f);
  if (stereo_baseline_m > 0) r.stereo = io::StereoRecord{f.right, stereo_baseline_m};
  return r;
}

/// Shades RGB (when selected, lit as `sun` says and, given one, with the EV100 `ev100`) and encodes every selected
/// output of `work`; the LiDAR sweep's files too when it has one.
void shade_and_encode_view(const world::WorldContext& ctx, const CaptureSettings& settings, FrameWork& work,
                           const FrameWork& sun, std::optional<float> ev100) {
  const world::PlannedFrame& f = work.frame;
  if (settings.outputs.has(io::OutputType::Rgb)) {
    shade_frame(ctx, work, sun, ev100);
  } else {
    work.shade_s = 0;
    work.bare_soil_pixels = 0;
  }
  work.pixels_by_role.fill(0);
  for (const Role r : work.gbuffer.role) ++work.pixels_by_role[uint8_t(r)];
  if (!f.right)  // blocked views are counted for the left camera
    work.near_pixels = uint64_t(std::count_if(work.gbuffer.depth.begin(), work.gbuffer.depth.end(),
                                              [](float d) { return d > 0.0f && d < kBlockedViewDepth; }));
  const Stopwatch clock;
  const io::LabelPlanes planes = label_planes(work.gbuffer);
  work.files = io::encode_capture_set(planes, work.rgb, settings.ontology, settings.outputs, f.frame, f.right);
  const io::OutputSelection& out = settings.outputs;
  work.card = io::count_planes(planes, work.lidar, settings.ontology, out.has(io::OutputType::Semantic),
                               out.has(io::OutputType::Instance), out.has(io::OutputType::Depth),
                               out.has(io::OutputType::Lidar));
  if (settings.outputs.has(io::OutputType::Lidar) && !f.right) {
    io::LidarLabels labels = io::semantic_kitti_labels(work.lidar, settings.ontology);
    work.files.push_back({io::frame_file("lidar", f.frame, "bin"), io::kitti_scan(work.lidar)});
    work.files.push_back({io::frame_file("lidar_labels", f.frame, "label"), std::move(labels.labels)});
    work.files.push_back({io::frame_file("lidar_labels", f.frame, "json"),
                          std::vector<uint8_t>(labels.instances_json.begin(), labels.instances_json.end())});
  }
  work.encode_s = clock.seconds();
}

/// Shades and encodes `work`'s view, and with a stereo baseline the left camera's disparity and the right
/// camera's view (the left's shadow map and exposure); then lets go of the sun maps (recycled for later frames).
void shade_and_encode(const world::WorldContext& ctx, const CaptureSettings& settings, FrameWork& work) {
  shade_and_encode_view(ctx, settings, work, work, std::nullopt);
  if (settings.stereo_baseline_m > 0) {
    const Stopwatch clock;
    const Camera& camera = work.frame.camera;
    const std::vector<uint16_t> disparity =
        io::kitti_disparity(work.gbuffer.depth, camera.fx, settings.stereo_baseline_m);
    work.files.push_back({io::frame_file("disparity", work.frame.frame, "png"),
                          io::encode_png_grey16(disparity, camera.width, camera.height)});
    work.encode_s += clock.seconds();
    shade_and_encode_view(ctx, settings, *work.right, work, work.ev100);
  }
  work.sun = nullptr;
}

/// InputError when `path` is a symbolic link (Silva writes only into real folders of the run folder).
void refuse_link(const fs::path& path) {
  std::error_code ec;
  if (fs::is_symlink(fs::symlink_status(path, ec)))
    throw InputError(path.string() + ": is a symbolic link; Silva writes a run's frames only into real folders "
                     "inside the run folder (replace the link with a folder)");
}

/// Writes one camera's files and camera JSON; adds its bytes and step times to `stats`.
void write_view(const Config& config, const CaptureSettings& settings, const FrameWork& work, CaptureStats& stats) {
  const Stopwatch clock;
  const fs::path seq = settings.run_dir / work.frame.sequence;
  for (const io::EncodedFile& file : work.files) {
    io::write_file_atomic(seq / file.relative_path, file.bytes);
    stats.bytes_written += file.bytes.size();
  }
  io::CameraRecord record = camera_record(config, work.frame, settings.stereo_baseline_m);
  record.lighting = lighting_record(work, settings.outputs.has(io::OutputType::Rgb));
  if (settings.outputs.has(io::OutputType::Rgb)) record.model = exposed_camera_model(record.model, work.ev100);
  const std::string camera = io::camera_json(record);
  io::write_file_atomic(settings.run_dir / camera_file(work.frame), camera);
  stats.bytes_written += camera.size();
  stats.write_s += clock.seconds();
  stats.render_s += work.render_s;
  stats.shadow_s += work.shadow_s;
  stats.shade_s += work.shade_s;
  stats.encode_s += work.encode_s;
  stats.triangles_submitted += work.triangles_submitted;
  stats.triangles_rasterised += work.triangles_rasterised;
}

/// Writes `work`'s files and camera JSON (the right camera's first, so the left camera file, written last, marks
/// the frame complete) and adds the frame to the writer's stats; labels are counted for the left camera.
void write_frame(const Config& config, const CaptureSettings& settings, const FrameWork& work, DatasetWriter& writer) {
  CaptureStats& stats = writer.stats;
  if (settings.stereo_baseline_m > 0) write_view(config, settings, *work.right, stats);
  write_view(config, settings, work, stats);
  stats.lidar_s += work.lidar_s;
  stats.lidar_points += work.lidar.size();
  for (int r = 0; r < kRoleCount; ++r) stats.pixels_by_role[size_t(r)] += work.pixels_by_role[size_t(r)];
  stats.bare_soil_pixels += work.bare_soil_pixels;
  if (double(work.near_pixels) >= kBlockedViewShare * double(work.gbuffer.depth.size())) {
    if (stats.blocked_views++ == 0) stats.first_blocked = work.frame.sequence + " frame " + std::to_string(work.frame.frame);
  }
  io::add_label_counts(stats.card.totals, work.card);
  stats.card.frames.emplace(work.frame.sequence, work.frame.frame);
  ++stats.frames_written;
  if (writer.progress) writer.progress(stats.frames_written, writer.total);
}

/// What lies on the world's forest floor: the season's fresh leaves and the forest type's litter and cones.
render::FloorLook floor_look(const world::WorldContext& ctx) {
  return {render::fallen_leaf_cover(ctx.season), ctx.forest ? float(ctx.forest->needle_litter) : -1.0f,
          ctx.forest ? float(ctx.forest->spruce_litter) : 0.0f};
}

}  // namespace

void shade_frame(const world::WorldContext& ctx, FrameWork& work, const FrameWork& sun, std::optional<float> ev100) {
  const world::PlannedFrame& f = work.frame;
  const Stopwatch clock;
  const render::FrameLighting& lighting = work.lighting;
  const std::shared_ptr<render::ShadeScratch> scratch = work.shade_scratches.take();
  const std::string noise_stream = io::camera_folder(f.sequence, f.right);
  const render::ShadeInputs in{work.gbuffer,     f.camera,
                               lighting.preset,  &sun.sun->shadow,
                               uint64_t(ctx.config.seed), noise_stream,
                               uint64_t(f.frame), frame_camera_model(ctx.config, f),
                               lighting.auto_exposure, lighting.exposure_compensation_ev,
                               lighting.white_balance, floor_look(ctx),
                               ev100,            &sun.sun->canopy,
                               ctx.trail_surface, ctx.config.camera.antialias,
                               scratch.get()};
  const render::ShadeCounts counts = render::shade_rgb(in, work.rgb);
  work.bare_soil_pixels = counts.bare_soil_pixels;
  work.ev100 = counts.ev100;
  if (ctx.config.camera.antialias) {
    render::smooth_edges(work.rgb, work.gbuffer.width, work.gbuffer.height, work.rgb_scratch);
    work.rgb.swap(work.rgb_scratch);
  }
  if (ctx.config.camera.jpeg_quality > 0)
    work.rgb = io::jpeg_round_trip(work.rgb, work.gbuffer.width, work.gbuffer.height, ctx.config.camera.jpeg_quality);
  work.shade_s = clock.seconds();
}

io::LabelPlanes label_planes(const render::GBuffer& g) {
  return {g.width, g.height, g.depth, g.normal, g.role, g.instance_id};
}

fs::path camera_file(const world::PlannedFrame& frame) {
  return fs::path(frame.sequence) / io::frame_file(io::camera_folder("camera", frame.right), frame.frame, "json");
}

void create_output_folders(const fs::path& run_dir, const std::vector<world::PlannedFrame>& frames,
                           const io::OutputSelection& outputs, bool stereo) {
  std::vector<std::string> names = {"camera"};
  for (int t = 0; t < io::kOutputTypeCount; ++t)
    if (outputs.has(io::OutputType(t))) names.push_back(io::output_type_name(io::OutputType(t)));
  if (outputs.has(io::OutputType::Lidar)) names.push_back("lidar_labels");
  if (stereo) {
    for (size_t k = 0, n = names.size(); k < n; ++k)
      if (names[k] != "lidar" && names[k] != "lidar_labels") names.push_back(io::camera_folder(names[k], true));
    names.push_back("disparity");
  }
  std::vector<std::string> sequences;
  for (const world::PlannedFrame& f : frames)
    if (std::find(sequences.begin(), sequences.end(), f.sequence) == sequences.end()) sequences.push_back(f.sequence);
  for (const std::string& sequence : sequences) {
    const fs::path seq = run_dir / sequence;
    // A link would send the frames outside the run folder (a resumed or sharded run finds folders in place).
    for (const fs::path& folder : {seq, seq / "camera"}) refuse_link(folder);
    for (const auto& n : names) {
      refuse_link(seq / n);
      std::error_code ec;
      fs::create_directories(seq / n, ec);
      if (ec) throw IoError("cannot create folder " + (seq / n).string() + ": " + ec.message());
    }
  }
}

size_t frames_in_flight(size_t threads) {
  if (threads <= 2) return threads == 2 ? kFramesInFlight : 1;
  return std::min(kMaxFramesInFlight, kFramesInFlightFromThree + (threads - 2) / kThreadsPerFrameInFlight);
}

void install_write_dataset(ecs::World& world) {
  world.set_resource(std::make_unique<DatasetWriter>());
  world.system("write_dataset")
      .phase(Phase::Write)
      .reads_resource<WorldSource, CaptureSettings>()
      .writes_resource<FrameSlots, std::unique_ptr<DatasetWriter>>()
      .run([](ecs::SystemContext& sys) {
        std::shared_ptr<FrameWork> work = std::move(sys.resource<FrameSlots>().current);
        if (!work) return;
        const world::WorldContext& ctx = *sys.resource<const WorldSource>().ctx;
        const CaptureSettings& settings = sys.resource<const CaptureSettings>();
        DatasetWriter& writer = *sys.resource<std::unique_ptr<DatasetWriter>>();
        writer.stage.submit([&ctx, &settings, work] { shade_and_encode(ctx, settings, *work); },
                            [&ctx, &settings, &writer, work] { write_frame(ctx.config, settings, *work, writer); });
      });
}

}  // namespace silva::systems
