#include "io/camera_json.hpp"

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "io/camera_model_json.hpp"
#include "io/json_read.hpp"

namespace silva::io {

std::string camera_json(const CameraRecord& r) {
  const Camera& c = r.camera;
  nlohmann::ordered_json j;
  j["frame"] = r.frame;
  j["sequence"] = r.sequence;
  j["perspective"] = r.perspective == Perspective::Aerial ? "aerial" : "ground";
  j["width"] = c.width;
  j["height"] = c.height;
  j["K"] = {{c.fx, 0.0, c.cx}, {0.0, c.fy, c.cy}, {0.0, 0.0, 1.0}};
  j["camera_to_world"] = matrix4_json(c.camera_to_world);
  j["near"] = c.near;
  j["far"] = c.far;
  j["yaw_deg"] = r.yaw_deg;
  j["pitch_deg"] = r.pitch_deg;
  j["roll_deg"] = r.roll_deg;
  j["trail_s"] = r.trail_s ? nlohmann::ordered_json(*r.trail_s) : nlohmann::ordered_json(nullptr);
  j["camera_model"] = camera_model_json(r.model);
  return j.dump(2) + "\n";
}

CameraRecord parse_camera_json(const std::string& text, const std::string& source) {
  const nlohmann::json j = parse_json_text(text, source);
  CameraRecord r;
  r.frame = int(json_int(j, "frame", 0, 999999, source));
  r.sequence = json_string(j, "sequence", source);
  const std::string perspective = json_string(j, "perspective", source);
  if (perspective != "ground" && perspective != "aerial")
    throw InputError(source + ": 'perspective' must be \"ground\" or \"aerial\", got \"" + perspective + "\"");
  r.perspective = perspective == "aerial" ? Perspective::Aerial : Perspective::Ground;
  Camera& c = r.camera;
  c.width = int(json_int(j, "width", 1, 1 << 20, source));
  c.height = int(json_int(j, "height", 1, 1 << 20, source));
  const auto k = json_matrix(j, "K", 3, 3, source);
  c.fx = k[0][0];
  c.fy = k[1][1];
  c.cx = k[0][2];
  c.cy = k[1][2];
  c.camera_to_world = read_matrix4(j, "camera_to_world", source);
  c.near = json_number(j, "near", source);
  c.far = json_number(j, "far", source);
  r.yaw_deg = json_number(j, "yaw_deg", source);
  r.pitch_deg = json_number(j, "pitch_deg", source);
  r.roll_deg = json_number(j, "roll_deg", source);
  if (!json_member(j, "trail_s", source).is_null()) r.trail_s = json_number(j, "trail_s", source);
  r.model = parse_camera_model(j, source);
  return r;
}

CameraRecord read_camera_json(const std::filesystem::path& path) {
  return parse_camera_json(read_text_file(path), path.string());
}

}  // namespace silva::io
