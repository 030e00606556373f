#pragma once
/// @file camera/NNNNNN.json (CONTRACT.md "File formats"): writer and reader.
#include <filesystem>
#include <optional>
#include <string>

#include "core/camera.hpp"
#include "core/camera_model.hpp"

namespace silva::io {

/// Height class of a capture ("ground" or "aerial" in the file).
enum class Perspective { Ground, Aerial };

/// Everything a camera file holds.
struct CameraRecord {
  int frame = 0;                        ///< Frame number within the sequence.
  std::string sequence;                 ///< "autopilot", "random" or "custom".
  Perspective perspective = Perspective::Ground;  ///< Ground or aerial capture.
  Camera camera;                        ///< Resolution, K, camera_to_world, near, far.
  double yaw_deg = 0, pitch_deg = 0, roll_deg = 0;  ///< Pose angles (CONTRACT.md convention).
  std::optional<double> trail_s;        ///< Arc length along the trail (autopilot) or none (null).
  CameraModel model;                    ///< Sensor noise and optics applied to the frame's RGB.
};

/// The camera file's text (keys in CONTRACT.md order, doubles printed to round-trip exactly).
std::string camera_json(const CameraRecord& record);

/// Parses camera file text; `source` (a path) names the file in InputError messages.
CameraRecord parse_camera_json(const std::string& text, const std::string& source);

/// Reads and parses a camera file; InputError if it is missing or malformed.
CameraRecord read_camera_json(const std::filesystem::path& path);

}  // namespace silva::io
