#pragma once
/// @file Pose files for the custom sequence (CONTRACT.md "pose file"): JSON or CSV.
#include <filesystem>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace silva::io {

/// One custom pose, in file order.
struct PoseEntry {
  Vec3d position = Vec3d::Zero();  ///< World position; z meaningful only when has_z.
  bool has_z = true;               ///< false: z omitted, the camera sits camera.ground_height above terrain.
  double yaw_deg = 0, pitch_deg = 0, roll_deg = 0;  ///< Given, or decomposed from the matrix.
  Mat3d rotation = Mat3d::Identity();  ///< Camera-to-world rotation: the file's matrix, or from the angles.
};

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
