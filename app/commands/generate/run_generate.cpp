// `silva generate` after the CLI checks: plan, prepare the run folder, capture, write manifests.
#include <filesystem>
#include <map>

#include "pipeline/console/interrupt.hpp"
#include "pipeline/console/progress.hpp"
#include "app/commands/card/card_command.hpp"
#include "app/commands/export/export_command.hpp"
#include "app/commands/generate/generate_command.hpp"
#include "app/commands/generate/run_manifest.hpp"
#include "pipeline/config/run_setup.hpp"
#include "core/error.hpp"
#include "core/rig_presets.hpp"
#include "core/stopwatch.hpp"
#include "io/atomic_file.hpp"
#include "io/capture_set.hpp"
#include "io/lidar_files.hpp"
#include "io/ontology_file.hpp"
#include "io/pose_file.hpp"
#include "io/run_folder.hpp"
#include "io/run_lock.hpp"
#include "io/sequence_flow.hpp"
#include "io/trajectory_files.hpp"
#include "pipeline/schedule/world_schedule.hpp"
#include "systems/cast_lidar.hpp"
#include "world/imu_model.hpp"
#include "world/trajectory.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

namespace fs = std::filesystem;

namespace {
/// Chunk cache bound: every chunk within the render distance of a camera, at least 256.
size_t cache_capacity(const Config& c) {
  const double r = c.world.render_distance + c.terrain.chunk_size;
  const double chunks = 3.14159265358979 * r * r / (c.terrain.chunk_size * c.terrain.chunk_size);
  return std::max<size_t>(256, size_t(chunks));
}

io::FolderMode folder_mode(const GenerateRequest& r) {
  if (r.shard) return io::FolderMode::Shard;
  if (r.resume) return io::FolderMode::Resume;
  if (r.overwrite) return io::FolderMode::Overwrite;
  return io::FolderMode::Fresh;
}

std::string shard_record_name(const Shard& s) {
  return "run.shard-" + std::to_string(s.index) + "-of-" + std::to_string(s.count) + ".json";
}

/// True when every file of frame `f` is in `run_dir`: its camera file (written last) and each selected output's.
bool frame_complete(const world::PlannedFrame& f, const io::OutputSelection& outputs, bool stereo,
                    const fs::path& run_dir) {
  std::error_code ec;
  if (!fs::is_regular_file(run_dir / systems::camera_file(f), ec)) return false;
  for (const std::string& file : io::frame_file_names(outputs, f.frame, stereo))
    if (!fs::is_regular_file(run_dir / f.sequence / file, ec)) return false;
  return true;
}

/// The planned frames this run captures: its shard's, less those already complete in `run_dir` (counted in
/// `skipped`); a frame with any file missing (deleted after it was written) is captured again.
std::vector<world::PlannedFrame> frames_to_capture(const std::vector<world::PlannedFrame>& plan,
                                                  const GenerateRequest& request, const io::OutputSelection& outputs,
                                                  const fs::path& run_dir, int& skipped) {
  std::vector<world::PlannedFrame> frames;
  for (const auto& f : plan) {
    if (request.shard && f.global_index % request.shard->count != request.shard->index) continue;
    if (frame_complete(f, outputs, stereo_baseline_m(request.config.config.rig) > 0, run_dir)) {
      ++skipped;
      continue;
    }
    frames.push_back(f);
  }
  return frames;
}

/// With output type lidar: each sequence's KITTI calib.txt and poses.txt (every planned frame, in
/// frame order), written before its frames.
void write_lidar_sequence_files(const std::vector<world::PlannedFrame>& plan, const fs::path& run_dir,
                                const Config& cfg) {
  std::map<std::string, std::map<int, const world::PlannedFrame*>> sequences;
  for (const world::PlannedFrame& f : plan) sequences[f.sequence][f.frame] = &f;
  for (const auto& [name, frames] : sequences) {
    std::vector<Mat4d> poses;
    for (const auto& [n, f] : frames) poses.push_back(f->camera.camera_to_world);
    fs::create_directories(run_dir / name);
    io::write_file_atomic(run_dir / name / "poses.txt", io::kitti_poses(poses));
    io::write_file_atomic(run_dir / name / "calib.txt",
                          io::kitti_calib(frames.begin()->second->camera, systems::lidar_to_camera(cfg.lidar)));
  }
}

/// Writes the trajectory sequence's IMU readings (imu.csv), their noise (imu.yaml), the true state at each reading
/// (state_groundtruth.csv, EuRoC) and its camera poses (groundtruth.txt, TUM; groundtruth_kitti.txt, KITTI odometry)
/// into <run_dir>/trajectory/ when the plan has that sequence.
void write_trajectory_files(const world::WorldContext& ctx, const std::vector<world::PlannedFrame>& plan,
                            const fs::path& run_dir) {
  std::vector<double> times;
  std::vector<Mat4d> poses;
  const TrajectoryConfig& tc = ctx.config.trajectory;
  for (const world::PlannedFrame& f : plan)
    if (f.sequence == "trajectory") {
      times.push_back(double(f.frame) / tc.camera_hz);
      poses.push_back(f.camera.camera_to_world);
    }
  if (times.empty()) return;
  const fs::path dir = run_dir / "trajectory";
  fs::create_directories(dir);
  const ImuNoise noise = world::imu_noise_model(tc.imu_noise);
  const world::Trajectory walk(ctx);
  const std::vector<ImuSample> imu = world::imu_samples(walk, tc.imu_hz, noise, uint64_t(ctx.config.seed));
  io::write_file_atomic(dir / "imu.csv", io::euroc_imu_csv(imu));
  io::write_file_atomic(dir / "state_groundtruth.csv", io::euroc_state_csv(world::imu_states(walk, tc.imu_hz, imu)));
  io::write_file_atomic(dir / "imu.yaml", io::kalibr_imu_yaml(noise, tc.imu_hz));
  io::write_file_atomic(dir / "groundtruth.txt", io::tum_trajectory(times, poses));
  io::write_file_atomic(dir / "groundtruth_kitti.txt", io::kitti_poses(poses));
}

/// Writes the finished run's output.formats into <run_dir>/export/ (as silva export).
void export_run_formats(const Config& cfg, const fs::path& run_dir, const Reporter& reporter) {
  if (cfg.output.formats.empty()) return;
  std::vector<io::ExportFormat> formats;
  for (const std::string& name : cfg.output.formats) formats.push_back(io::parse_export_format(name, "output.formats"));
  export_formats(io::open_dataset(run_dir), formats, run_dir / "export", /*overwrite=*/true);
  reporter.note("silva: exported " + std::to_string(formats.size()) + " formats into " + (run_dir / "export").string());
}

/// Prints the run's summary: a JSON object with --json, else one line.
/// Warns when views of the run were blocked (systems::kBlockedViewShare of their pixels nearer than kBlockedViewDepth).
void warn_blocked_views(const Reporter& reporter, const systems::CaptureStats& stats) {
  if (stats.blocked_views == 0) return;
  char rule[96];
  std::snprintf(rule, sizeof rule, "at least %.0f %% of their pixels see a surface nearer than %.1f m",
                100.0 * systems::kBlockedViewShare, double(systems::kBlockedViewDepth));
  reporter.warn(std::to_string(stats.blocked_views) + " of " + std::to_string(stats.frames_written) +
                " views are blocked: " + rule + " (the camera inside foliage or against bark; first: " +
                stats.first_blocked + "); run.json's blocked_views counts them");
}

void report_summary(const Reporter& reporter, const systems::CaptureStats& stats, const nlohmann::json& record,
                    int64_t seed, const fs::path& run_dir, int skipped, size_t planned, double card_s) {
  const double fps = stats.wall_s > 0 ? stats.frames_written / stats.wall_s : 0.0;
  nlohmann::json summary = {{"ok", true},
                            {"seed", seed},
                            {"run_dir", run_dir.string()},
                            {"frames_written", stats.frames_written},
                            {"frames_skipped_complete", skipped},
                            {"frames_planned", planned},
                            {"bytes_written", stats.bytes_written},
                            {"wall_s", stats.wall_s},
                            {"frames_per_s", fps},
                            {"timings_s", record["timings_s"]},
                            {"card_s", card_s}};
  if (record.contains("shard")) summary["shard"] = record["shard"];
  char line[256];
  std::snprintf(line, sizeof line, "wrote %d frames (%.1f MB) in %.1f s (%.2f frames/s) to %s", stats.frames_written,
                stats.bytes_written / 1e6, stats.wall_s, fps, run_dir.string().c_str());
  reporter.result(summary, line);
}
}  // namespace

int run_generate(const GenerateRequest& request, const Reporter& reporter) {
  LoadedConfig loaded = request.config;
  const Config& cfg = loaded.config;
  if (request.shard && request.overwrite)
    throw InputError("--overwrite cannot be combined with --shard (shards share one folder); empty it first");
  const bool seed_from_marker = !loaded.seed_given;
  if (seed_from_marker) {
    loaded.config.seed = io::find_resumable_seed(cfg.output.dir);
    loaded.seed_given = true;
  }

  const Stopwatch plan_clock;
  RunSetup setup = make_run_setup(loaded);
  const io::OutputSelection outputs = io::OutputSelection::from_names(cfg.output.types);
  std::vector<PoseEntry> poses;
  if (std::find(cfg.captures.sequences.begin(), cfg.captures.sequences.end(), "custom") != cfg.captures.sequences.end())
    poses = io::read_pose_file(cfg.captures.poses_file);
  WorldSchedule schedule(setup.world, cache_capacity(cfg));
  const std::vector<world::PlannedFrame>& plan =
      schedule.plan(std::move(poses), [&](const std::string& w) { reporter.warn(w); });
  const double plan_s = plan_clock.seconds();

  // From here on files are written: an interrupt asks for a clean stop. The run folder is locked
  // for the whole run (shards share it), so no other writer mixes frames into it.
  begin_writing();
  const io::RunLock lock = io::lock_run_folder(fs::path(cfg.output.dir) / io::seed_folder_name(cfg.seed),
                                               /*exclusive=*/!request.shard);
  const fs::path run_dir = io::prepare_run_folder(cfg.output.dir, cfg.seed, run_identity_hash(loaded, setup),
                                                  folder_mode(request), resumable_config_text(loaded));
  // Noted once every input is checked, so bad input prints only its error line (a seed drawn
  // from the clock was noted when it was drawn).
  if (!loaded.seed_from_clock)
    reporter.note("silva: seed " + io::seed_folder_name(cfg.seed) + (seed_from_marker ? " (from the run folder)" : ""));
  io::write_file_atomic(run_dir / "ontology.json", io::ontology_json(setup.ontology));
  if (outputs.has(io::OutputType::Lidar)) write_lidar_sequence_files(plan, run_dir, cfg);
  write_trajectory_files(setup.world, plan, run_dir);

  int skipped = 0;
  const std::vector<world::PlannedFrame> frames = frames_to_capture(plan, request, outputs, run_dir, skipped);
  reporter.note("silva: capturing " + std::to_string(frames.size()) + " frames at " +
                std::to_string(cfg.output.width) + "x" + std::to_string(cfg.output.height) + " into " +
                run_dir.string() + (skipped ? " (" + std::to_string(skipped) + " already complete)" : ""));

  Progress progress(reporter, int(frames.size()), "frames");
  const systems::CaptureStats stats =
      schedule.capture(frames, {setup.lighting, setup.ontology, outputs, run_dir, setup.lidar, stereo_baseline_m(cfg.rig)},
                       [&](int done, int) { progress.update(done); }, [] { return interrupt_requested(); });
  progress.finish();
  warn_blocked_views(reporter, stats);

  nlohmann::json record = make_run_record(stats, request.threads, skipped, plan_s);
  record["poses"] = count_pose_fixes(plan);
  const nlohmann::json manifest = make_manifest(loaded, setup, count_frames(plan));
  if (stats.stopped) {
    io::write_file_atomic(run_dir / "run.json", record.dump(2) + "\n");
    throw Interrupted("interrupted after " + std::to_string(stats.frames_written) +
                      " frames; continue with: silva generate --resume --out " + cfg.output.dir + " --seed " +
                      std::to_string(cfg.seed));
  }
  double card_s = 0;
  if (request.shard) {
    record["shard"] = {{"index", request.shard->index}, {"count", request.shard->count}};
    record["manifest"] = manifest;
    record["frames_total"] = plan.size();
    io::write_file_atomic(run_dir / shard_record_name(*request.shard), record.dump(2) + "\n");
  } else {
    io::write_file_atomic(run_dir / "run.json", record.dump(2) + "\n");
    io::write_file_atomic(run_dir / "manifest.json", manifest.dump(2) + "\n");
    if (const int files = io::write_trajectory_flow(run_dir))
      reporter.note("silva: wrote " + std::to_string(files) + " optical flow files into " + (run_dir / "trajectory").string());
    export_run_formats(cfg, run_dir, reporter);
    const Stopwatch card_clock;
    write_card(run_dir, {&stats.card, &schedule, &setup});
    card_s = card_clock.seconds();
  }
  report_summary(reporter, stats, record, cfg.seed, run_dir, skipped, plan.size(), card_s);
  return 0;
}

}  // namespace silva::app
