#pragma once
/// @file The "camera_model" object of a camera file (CONTRACT.md "File formats"): the sensor
/// noise and optics applied to the frame's RGB. Writer and reader.
#include <nlohmann/json.hpp>
#include <string>

#include "core/camera_model.hpp"
#include "core/types.hpp"

namespace silva::io {

/// A 4x4 matrix as a row-major nested list.
nlohmann::ordered_json matrix4_json(const Mat4d& m);

/// The 4x4 row-major nested list `key` of `obj`; InputError naming `where` and the key otherwise.
Mat4d read_matrix4(const nlohmann::json& obj, const std::string& key, const std::string& where);

/// {"noise", "vignetting", "chromatic_aberration", "bloom", "chroma", "jpeg_quality", "depth_of_field",
/// "motion_blur"}; an effect that is off is null (or 0).
nlohmann::ordered_json camera_model_json(const CameraModel& model);

/// Parses camera_model_json's object; `where` names the file in InputError messages.
CameraModel parse_camera_model(const nlohmann::json& obj, const std::string& where);

}  // namespace silva::io
