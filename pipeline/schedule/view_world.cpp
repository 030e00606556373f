#include "pipeline/schedule/view_world.hpp"

#include <cmath>
#include <utility>

#include "core/error.hpp"
#include "core/stopwatch.hpp"
#include "io/atomic_file.hpp"
#include "io/jpeg_writer.hpp"
#include "io/json_read.hpp"
#include "io/label_images.hpp"
#include "io/ontology_file.hpp"
#include "io/output_types.hpp"
#include "io/png_writer.hpp"
#include "io/pose_file.hpp"
#include "io/run_folder.hpp"
#include "io/run_lock.hpp"
#include "systems/write_dataset.hpp"
#include "world/terrain.hpp"

namespace silva::pipeline {

namespace fs = std::filesystem;

namespace {

/// Grey bytes as R = G = B.
std::vector<uint8_t> grey_to_rgb(const std::vector<uint8_t>& grey) {
  std::vector<uint8_t> rgb(grey.size() * 3);
  for (size_t i = 0; i < grey.size(); ++i) rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = grey[i];
  return rgb;
}

/// A distinct, bright colour per instance id (a multiplicative hash); black for none.
std::vector<uint8_t> instance_colours(const std::vector<uint32_t>& ids) {
  std::vector<uint8_t> rgb(ids.size() * 3, 0);
  for (size_t i = 0; i < ids.size(); ++i) {
    if (ids[i] == 0) continue;
    const uint32_t h = ids[i] * 2654435761u;
    rgb[3 * i] = uint8_t(64 + (h >> 24) % 192);
    rgb[3 * i + 1] = uint8_t(64 + (h >> 16) % 192);
    rgb[3 * i + 2] = uint8_t(64 + (h >> 8) % 192);
  }
  return rgb;
}

/// The output selection a mode renders: rgb (with its shadow map) only for the RGB view.
io::OutputSelection mode_outputs(ViewMode mode) {
  return io::OutputSelection::from_names({mode == ViewMode::Rgb ? "rgb" : "semantic"});
}

/// The chunks of the capture region (the world.extent square about the origin), (i, j) order.
std::vector<ChunkCoord> capture_region_chunks(const Config& cfg) {
  const double s = cfg.terrain.chunk_size, h = cfg.world.extent / 2;
  std::vector<ChunkCoord> coords;
  for (int i = int(std::floor(-h / s)); i < int(std::ceil(h / s)); ++i)
    for (int j = int(std::floor(-h / s)); j < int(std::ceil(h / s)); ++j) coords.push_back({i, j});
  return coords;
}

}  // namespace

bool parse_view_mode(std::string_view name, ViewMode& mode) {
  constexpr std::pair<std::string_view, ViewMode> kModes[] = {{"rgb", ViewMode::Rgb},
                                                              {"semantic", ViewMode::Semantic},
                                                              {"instance", ViewMode::Instance},
                                                              {"depth", ViewMode::Depth},
                                                              {"normal", ViewMode::Normal}};
  for (const auto& [n, m] : kModes)
    if (n == name) {
      mode = m;
      return true;
    }
  return false;
}

std::vector<uint8_t> view_image(const world::WorldContext& ctx, const systems::CaptureSettings& settings, ViewMode mode,
                                systems::FrameWork& work) {
  const io::LabelPlanes planes = systems::label_planes(work.gbuffer);
  switch (mode) {
    case ViewMode::Rgb:
      systems::shade_frame(ctx, work, work, std::nullopt);
      return work.rgb;
    case ViewMode::Semantic:
      return io::semantic_color_image(planes, settings.ontology);
    case ViewMode::Instance:
      return instance_colours(work.gbuffer.instance_id);
    case ViewMode::Depth:
      return grey_to_rgb(io::depth_preview_image(planes));
    case ViewMode::Normal:
      return io::normal_image(planes);
  }
  return {};
}

ViewWorld::ViewWorld(LoadedConfig loaded) : loaded_(std::move(loaded)), setup_(make_run_setup(loaded_)) {
  schedule_ = std::make_unique<WorldSchedule>(setup_.world, 256);
  crowns_ = std::make_unique<world::CrownProfiles>(*setup_.library);
}

bool ViewWorld::blocked(const Vec3d& eye) {
  const world::WorldContext& ctx = setup_.world;
  ScheduleChunks chunks(*schedule_);
  return !world::ClearanceProbe::around(ctx, chunks, *crowns_, eye.x(), eye.y(), 0.0).column_clear(eye);
}

world::PlannedFrame ViewWorld::view_frame(const ViewPose& pose, int width, int height) const {
  PoseEntry entry;
  entry.position = pose.position;
  entry.has_z = !pose.walk;
  entry.yaw_deg = pose.yaw_deg;
  entry.pitch_deg = pose.pitch_deg;
  entry.rotation = rotation_from_angles(pose.yaw_deg, pose.pitch_deg, 0);
  world::PlannedFrame f = world::plan_custom(setup_.world, {entry}).front();
  f.sequence = "view";
  const Config& cfg = setup_.world.config;
  Camera camera = Camera::from_fov(width, height, cfg.camera.fov_deg, cfg.camera.near, cfg.camera.far);
  camera.camera_to_world = f.camera.camera_to_world;
  f.camera = camera;
  return f;
}

ViewFrame ViewWorld::render(const ViewPose& pose, ViewMode mode, int width, int height) {
  const std::lock_guard lock(mutex_);
  const Stopwatch clock;
  world::PlannedFrame frame = view_frame(pose, width, height);
  bool refused = false;
  if (pose.walk && pose.from && blocked(frame.camera.position())) {
    ViewPose back = pose;
    back.position.head<2>() = *pose.from;
    const world::PlannedFrame there = view_frame(back, width, height);
    refused = !blocked(there.camera.position());
    if (refused) frame = there;
  }
  const systems::CaptureSettings settings{setup_.lighting, setup_.ontology, mode_outputs(mode), {}, {}};
  std::shared_ptr<systems::FrameWork> work = schedule_->render_view(frame, settings);
  ViewFrame out;
  out.schedule_ms = clock.seconds() * 1e3;
  out.raster_ms = (work->render_s + work->shadow_s) * 1e3;
  const std::vector<uint8_t> image = view_image(setup_.world, settings, mode, *work);
  out.shade_ms = clock.seconds() * 1e3 - out.schedule_ms;
  out.jpeg = io::encode_jpeg_rgb8(image, width, height, kViewJpegQuality);
  out.encode_ms = clock.seconds() * 1e3 - out.schedule_ms - out.shade_ms;
  out.position = frame.camera.position();
  out.blocked = refused;
  out.ground_z = world::terrain_height(setup_.world.terrain, out.position.x(), out.position.y());
  out.render_ms = clock.seconds() * 1e3;
  last_ = std::move(work);
  return out;
}

nlohmann::json ViewWorld::probe(double u, double v) const {
  const std::lock_guard lock(mutex_);
  if (!last_ || !(u >= 0 && u < 1 && v >= 0 && v < 1)) return {{"hit", false}};
  const render::GBuffer& g = last_->gbuffer;
  const size_t i = size_t(int(v * g.height)) * size_t(g.width) + size_t(int(u * g.width));
  const Role role = g.role[i];
  return {{"hit", g.depth[i] > 0},
          {"class", setup_.ontology.classes[uint8_t(role)].name},
          {"class_id", setup_.ontology.id(role)},
          {"instance_id", g.instance_id[i]},
          {"depth_m", g.depth[i]}};
}

nlohmann::json ViewWorld::capture(const ViewPose& pose) {
  const std::lock_guard lock(mutex_);
  const Config& cfg = loaded_.config;
  const fs::path pose_path = fs::path(cfg.output.dir) / io::seed_folder_name(cfg.seed) / "poses.json";
  // The run folder's marker names the config that reproduces it: this one, capturing the custom
  // sequence of the pose file.
  LoadedConfig record = loaded_;
  record.config.captures.sequences = {"custom"};
  record.config.captures.poses_file = pose_path.string();
  // Its identity leaves the growing pose file out (each capture appends to it), so every capture
  // of this view continues the same folder; `generate --resume` there sees another identity.
  LoadedConfig identity = record;
  identity.config.captures.sequences.clear();
  const fs::path run_dir = io::prepare_run_folder(cfg.output.dir, cfg.seed, run_identity_hash(identity, setup_),
                                                  io::FolderMode::Resume, resumable_config_text(record));
  // Held through the capture, so a generate, a merge or another view never writes this folder at the same time,
  // and the pose file is read and extended by one writer at a time.
  const io::RunLock folder_lock = io::lock_run_folder(run_dir, /*exclusive=*/true);

  nlohmann::json poses = fs::exists(pose_path) ? io::parse_json_text(io::read_text_file(pose_path), pose_path.string())
                                               : nlohmann::json{{"poses", nlohmann::json::array()}};
  if (!poses.is_object() || !poses.contains("poses") || !poses["poses"].is_array())
    throw InputError(pose_path.string() + ": not a pose file of the view ({\"poses\": [...]}); move it away");
  const Vec3d p = view_frame(pose, 16, 16).camera.position();
  poses["poses"].push_back({{"position", {p.x(), p.y(), p.z()}},
                            {"yaw_deg", pose.yaw_deg},
                            {"pitch_deg", pose.pitch_deg},
                            {"roll_deg", 0.0}});
  const std::string text = poses.dump(2) + "\n";
  // Planned from the file's own text, as `generate` reads it back.
  const std::vector<PoseEntry> entries = io::parse_pose_json(text, pose_path.string());
  world::PlannedFrame frame = world::plan_custom(setup_.world, {entries.back()}).front();
  frame.frame = int(entries.size()) - 1;
  frame.global_index = frame.frame;

  io::write_file_atomic(run_dir / "ontology.json", io::ontology_json(setup_.ontology));
  const io::OutputSelection outputs = io::OutputSelection::from_names(cfg.output.types);
  const systems::CaptureStats stats =
      schedule_->capture({frame}, {setup_.lighting, setup_.ontology, outputs, run_dir, {}}, {}, {});
  if (stats.frames_written != 1) throw IoError("the capture of frame " + std::to_string(frame.frame) + " failed");
  io::write_file_atomic(pose_path, text);
  return {{"frame", frame.frame},
          {"run_dir", run_dir.string()},
          {"poses_file", pose_path.string()},
          {"camera_file", (run_dir / systems::camera_file(frame)).string()}};
}

std::pair<std::vector<uint8_t>, nlohmann::json> ViewWorld::class_map() {
  const std::lock_guard lock(map_mutex_);
  if (!map_) {
    const Config& cfg = setup_.world.config;
    const world::BuiltWorld built = build_world(setup_.world, capture_region_chunks(cfg), 1);
    const double mpp = std::max(0.5, cfg.world.extent / 512);
    const world::ClassMap map =
        world::render_class_map(built, cfg.terrain.chunk_size, *setup_.library, setup_.ontology, mpp);
    map_.emplace(io::encode_png_rgb8(map.rgb, map.width, map.height),
                 nlohmann::json{{"x0", map.x0},
                                {"y1", map.y1},
                                {"metres_per_pixel", map.metres_per_pixel},
                                {"width", map.width},
                                {"height", map.height}});
  }
  return *map_;
}

nlohmann::json ViewWorld::trail(double step) const {
  nlohmann::json points = nlohmann::json::array();
  const world::NavSpline& nav = setup_.world.trail.nav;
  if (!setup_.world.trail.enabled || nav.length() <= 0) return points;
  for (double s = 0; s <= nav.length(); s += step) {
    const Vec3d p = nav.position(s), t = nav.tangent(s);
    points.push_back({p.x(), p.y(), p.z(), std::atan2(t.y(), t.x()) * 180 / 3.14159265358979323846});
  }
  return points;
}

ViewPose ViewWorld::start_pose() const {
  ViewPose pose;
  pose.walk = true;
  const nlohmann::json t = trail(1.0);
  if (!t.empty()) {
    pose.position = Vec3d(t[0][0].get<double>(), t[0][1].get<double>(), 0);
    pose.yaw_deg = t[0][3].get<double>();
  }
  return pose;
}

}  // namespace silva::pipeline
