#pragma once
/// @file manifest.json (deterministic) and run.json (varies) of a dataset (CONTRACT.md).
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "pipeline/config/run_setup.hpp"
#include "systems/write_dataset.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

/// The manifest: Silva version, resolved config without output.dir, sha256 of the lighting,
/// ontology and asset-library files, seed, frame counts per sequence, and the sensors ("sensors": {"cameras":
/// camera_descriptions, with the trajectory sequence "imu": imu_description, with output type lidar "lidar":
/// lidar_description}).
nlohmann::json make_manifest(const LoadedConfig& loaded, const RunSetup& setup,
                             const std::map<std::string, int>& frames_per_sequence);

/// The LiDAR of the manifest's "sensors": its preset's numbers, axes, mount and presets file sha256.
nlohmann::json lidar_description(const LoadedConfig& loaded, const RunSetup& setup);

/// The manifest's "sensors"."cameras": each camera of the rig with its name, output folders, camera-file folder and
/// camera_to_rig transform (the rig frame is the left or only camera's, OpenCV axes); a stereo rig's left camera
/// also names its disparity folder.
nlohmann::json camera_descriptions(const RigConfig& rig);

/// The manifest's "sensors"."imu" of a run with the trajectory sequence: rate, noise model, pose on the rig, files.
nlohmann::json imu_description(const TrajectoryConfig& trajectory);

/// Frames per sequence of a plan.
std::map<std::string, int> count_frames(const std::vector<world::PlannedFrame>& frames);

/// Clearance counts of a plan for run.json: {"checked", "moved", "unresolvable"} over its
/// autopilot and random poses (world::PoseFix; custom poses are not checked).
nlohmann::json count_pose_fixes(const std::vector<world::PlannedFrame>& frames);

/// run.json: timings per phase, counts, thread count, host, date, git revision.
nlohmann::json make_run_record(const systems::CaptureStats& stats, int threads, int skipped, double plan_s);

}  // namespace silva::app
