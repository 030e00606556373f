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

/// The lighting a frame was captured under: written when lighting.randomize is enabled or the
/// exposure is automatic (CONTRACT.md "File formats"), else absent.
struct LightingRecord {
  std::string time_of_day;            ///< The time-of-day preset's name.
  std::string weather;                ///< The weather preset's name (drawn when randomised).
  bool randomized = false;            ///< Whether the values below were drawn for this frame.
  double sun_elevation_deg = 0;       ///< Elevation of the sun (or moon), degrees.
  double sun_azimuth_deg = 0;         ///< Azimuth of the sun, degrees counter-clockwise from world +X.
  double cloud_cover = 0;             ///< The time of day's cloud cover (the weather's cloud_cover_min still applies).
  double fog_density_scale = 1;       ///< Factor on the time of day's fog_density (the weather's scale still applies).
  double white_balance_k = 6504;      ///< Colour temperature the camera balanced for, kelvin.
  std::string exposure = "preset";    ///< "preset" or "auto".
  double exposure_compensation_ev = 0;  ///< EV added to the image's brightness.
  std::optional<double> ev100;        ///< The EV100 the RGB was exposed with, or none (no rgb output).
  bool operator==(const LightingRecord&) const = default;
};

/// The camera's place in a stereo pair (CONTRACT.md "File formats"): written by a stereo rig, else absent.
struct StereoRecord {
  bool right = false;     ///< The right camera ("right" in the file), else the left ("left").
  double baseline_m = 0;  ///< Distance between the pair's optical centres, metres (the right is along the left's +x).
  bool operator==(const StereoRecord&) const = default;
};

/// Everything a camera file holds.
struct CameraRecord {
  int frame = 0;                        ///< Frame number within the sequence.
  std::string sequence;                 ///< "autopilot", "random", "custom" or "trajectory".
  Perspective perspective = Perspective::Ground;  ///< Ground or aerial capture.
  Camera camera;                        ///< Resolution, K, camera_to_world, near, far.
  double yaw_deg = 0, pitch_deg = 0, roll_deg = 0;  ///< Pose angles (CONTRACT.md convention).
  std::optional<double> trail_s;        ///< Arc length along the trail (autopilot) or none (null).
  CameraModel model;                    ///< Sensor noise and optics applied to the frame's RGB.
  std::optional<LightingRecord> lighting;  ///< The frame's lighting, when randomised or auto-exposed.
  std::optional<StereoRecord> stereo;      ///< The camera's place in a stereo pair, or none (one camera).
};

/// The camera file's text (keys in CONTRACT.md order, doubles printed to round-trip exactly).
std::string camera_json(const CameraRecord& record);

/// Parses camera file text; `source` (a path) names the file in InputError messages.
CameraRecord parse_camera_json(const std::string& text, const std::string& source);

/// Reads and parses a camera file; InputError if it is missing or malformed.
CameraRecord read_camera_json(const std::filesystem::path& path);

}  // namespace silva::io
