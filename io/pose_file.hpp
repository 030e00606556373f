#pragma once
/// @file Pose files for the custom sequence (CONTRACT.md "pose file"): JSON or CSV.
#include <filesystem>
#include <string>
#include <vector>

#include "core/pose_entry.hpp"
#include "core/types.hpp"

namespace silva::io {

using silva::PoseEntry;

/// Largest |R^T R - I| entry accepted for a pose matrix.
inline constexpr double kOrthonormalTolerance = 1e-5;

/// Parses JSON pose text {"poses": [...]}; each entry is {"position": [x, y(, z)], "yaw_deg",
/// "pitch_deg", "roll_deg"} or {"camera_to_world": 4x4}. InputError names `source` and the pose.
std::vector<PoseEntry> parse_pose_json(const std::string& text, const std::string& source);

/// Parses CSV pose text with header x,y,z,yaw_deg,pitch_deg,roll_deg (an empty z = omitted).
/// InputError names `source`, the line and the pose index.
std::vector<PoseEntry> parse_pose_csv(const std::string& text, const std::string& source);

/// Reads a pose file: ".csv" (any case) as CSV, anything else as JSON. At least one pose.
std::vector<PoseEntry> read_pose_file(const std::filesystem::path& path);

}  // namespace silva::io
