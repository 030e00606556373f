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
/// ontology and asset-library files, seed, frame counts per sequence, and with output type lidar
/// the sensor ("sensors": {"lidar": lidar_description}).
nlohmann::json make_manifest(const LoadedConfig& loaded, const RunSetup& setup,
                             const std::map<std::string, int>& frames_per_sequence);

/// The LiDAR of the manifest's "sensors": its preset's numbers, axes, mount and presets file sha256.
nlohmann::json lidar_description(const LoadedConfig& loaded, const RunSetup& setup);

/// Frames per sequence of a plan.
std::map<std::string, int> count_frames(const std::vector<world::PlannedFrame>& frames);

/// Clearance counts of a plan for run.json: {"checked", "moved", "unresolvable"} over its
/// autopilot and random poses (world::PoseFix; custom poses are not checked).
nlohmann::json count_pose_fixes(const std::vector<world::PlannedFrame>& frames);

/// run.json: timings per phase, counts, thread count, host, date, git revision.
nlohmann::json make_run_record(const systems::CaptureStats& stats, int threads, int skipped, double plan_s);

}  // namespace silva::app
