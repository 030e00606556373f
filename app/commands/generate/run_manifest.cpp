#include "app/commands/generate/run_manifest.hpp"

#include <unistd.h>

#include <chrono>
#include <ctime>

#include "pipeline/console/version.hpp"
#include "pipeline/config/config_print.hpp"
#include "core/rig_presets.hpp"
#include "io/sha256.hpp"
#include "systems/cast_lidar.hpp"
#include "app/cli/pipeline_names.hpp"
#include "app/cli/simd_limit.hpp"

namespace silva::app {

std::map<std::string, int> count_frames(const std::vector<world::PlannedFrame>& frames) {
  std::map<std::string, int> counts;
  for (const auto& f : frames) counts[f.sequence]++;
  return counts;
}

namespace {

/// A 4x4 transform as 4 rows: the identity moved `x` metres along x.
nlohmann::json translation_rows(double x) {
  return {{1.0, 0.0, 0.0, x}, {0.0, 1.0, 0.0, 0.0}, {0.0, 0.0, 1.0, 0.0}, {0.0, 0.0, 0.0, 1.0}};
}

}  // namespace

nlohmann::json camera_descriptions(const RigConfig& rig) {
  const double baseline = stereo_baseline_m(rig);
  nlohmann::json cameras = nlohmann::json::array();
  cameras.push_back({{"name", baseline > 0 ? "left" : "camera"},
                     {"folders", "<type>/"},
                     {"camera_files", "camera/"},
                     {"camera_to_rig", translation_rows(0.0)}});
  if (baseline > 0) {
    cameras[0]["disparity"] = "disparity/";
    cameras.push_back({{"name", "right"},
                       {"folders", "<type>_right/"},
                       {"camera_files", "camera_right/"},
                       {"camera_to_rig", translation_rows(baseline)}});
  }
  return cameras;
}

nlohmann::json imu_description(const TrajectoryConfig& trajectory) {
  return {{"rate_hz", trajectory.imu_hz},
          {"noise", trajectory.imu_noise},
          {"imu_to_rig", translation_rows(0.0)},
          {"frame", "the camera's: x right, y down, z forward"},
          {"files", "trajectory/imu.csv, trajectory/imu.yaml"}};
}

nlohmann::json make_manifest(const LoadedConfig& loaded, const RunSetup& setup,
                             const std::map<std::string, int>& frames_per_sequence) {
  nlohmann::json config = config_to_json(loaded);
  config["output"].erase("dir");
  config["output"].erase("formats");
  nlohmann::json frames = nlohmann::json::object();
  for (const auto& [sequence, n] : frames_per_sequence) frames[sequence] = n;
  nlohmann::json manifest = {
      {"silva_version", silva_version()},
      {"seed", loaded.config.seed},
      {"config", config},
      {"sha256",
       {{"lighting", io::sha256_file(setup.lighting_toml)},
        {"ontology", io::sha256_file(setup.ontology_json)},
        {"asset_library", io::sha256_file(setup.library_json)}}},
      {"frames", frames},
  };
  manifest["sensors"]["cameras"] = camera_descriptions(loaded.config.rig);
  if (frames_per_sequence.count("trajectory")) manifest["sensors"]["imu"] = imu_description(loaded.config.trajectory);
  if (io::OutputSelection::from_names(loaded.config.output.types).has(io::OutputType::Lidar))
    manifest["sensors"]["lidar"] = lidar_description(loaded, setup);
  if (frames_per_sequence.count("custom"))
    manifest["sha256"]["poses_file"] = io::sha256_file(loaded.config.captures.poses_file);
  if (!setup.world.walk_poses.empty())
    manifest["sha256"]["trajectory_file"] = io::sha256_file(loaded.config.trajectory.file);
  return manifest;
}

nlohmann::json lidar_description(const LoadedConfig& loaded, const RunSetup& setup) {
  const raycast::LidarPreset& p = setup.lidar;
  const Mat4d m = systems::lidar_to_camera(loaded.config.lidar);
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 4; ++r) rows.push_back({m(r, 0), m(r, 1), m(r, 2), m(r, 3)});
  return {{"preset", p.name},
          {"channels", p.elevations_deg.size()},
          {"elevations_deg", p.elevations_deg},
          {"columns", p.columns},
          {"rotation_hz", p.rotation_hz},
          {"min_range", p.min_range},
          {"max_range", p.max_range},
          {"range_noise_m", p.range_noise_m},
          {"dropout", p.dropout},
          {"intensity_falloff", p.intensity_falloff},
          {"intensity_noise", p.intensity_noise},
          {"frame", "x forward, y left, z up"},
          {"lidar_to_camera", rows},
          {"presets_sha256", io::sha256_file(setup.lidar_toml)}};
}

namespace {
/// What the frames written show: each class's share of all pixels (role names, zeros included)
/// and the share of all pixels whose forest floor looks like bare soil.
nlohmann::json pixel_shares(const systems::CaptureStats& s) {
  uint64_t total = 0;
  for (uint64_t n : s.pixels_by_role) total += n;
  const auto share = [&](uint64_t n) { return total ? double(n) / double(total) : 0.0; };
  nlohmann::json by_class = nlohmann::json::object();
  for (int r = 0; r < kRoleCount; ++r) by_class[role_name(Role(r))] = share(s.pixels_by_role[size_t(r)]);
  return {{"pixels", total}, {"by_class", by_class}, {"bare_soil_look", share(s.bare_soil_pixels)}};
}

/// {system name: seconds} of each ECS system's wall time over the run.
nlohmann::json system_seconds(const systems::CaptureStats& s) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, seconds] : s.system_s) j[name] = seconds;
  return j;
}
}  // namespace

nlohmann::json count_pose_fixes(const std::vector<world::PlannedFrame>& frames) {
  int checked = 0, moved = 0, unresolvable = 0;
  for (const world::PlannedFrame& f : frames) {
    if (f.sequence == "custom") continue;
    ++checked;
    moved += f.pose_fix == world::PoseFix::Moved ? 1 : 0;
    unresolvable += f.pose_fix == world::PoseFix::Unresolvable ? 1 : 0;
  }
  return {{"checked", checked}, {"moved", moved}, {"unresolvable", unresolvable}};
}

nlohmann::json make_run_record(const systems::CaptureStats& s, int threads, int skipped, double plan_s) {
  char host[256] = {};
  gethostname(host, sizeof host - 1);
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return {
      {"silva_version", silva_version()},
      {"git_revision", git_revision()},
      {"threads", threads},
      {"host", host},
      {"simd", {{"targets", simd_targets()},
                {"limit", simd_limit().empty() ? nlohmann::json(nullptr) : nlohmann::json(simd_limit())}}},
      {"date", date},
      {"frames_written", s.frames_written},
      {"frames_skipped_complete", skipped},
      {"bytes_written", s.bytes_written},
      {"chunks_generated", s.chunks_generated},
      {"triangles_submitted", s.triangles_submitted},
      {"triangles_rasterised", s.triangles_rasterised},
      {"pixel_shares", pixel_shares(s)},
      {"blocked_views", {{"count", s.blocked_views}, {"first", s.first_blocked}}},
      {"timings_s",
       {{"plan", plan_s},
        {"stream", s.stream_s},
        {"prepare", s.prepare_s},
        {"render", s.render_s},
        {"shadow", s.shadow_s},
        {"shade", s.shade_s},
        {"encode", s.encode_s},
        {"write", s.write_s},
        {"lidar", s.lidar_s},
        {"wall", s.wall_s}}},
      {"systems_s", system_seconds(s)},
  };
}

}  // namespace silva::app
