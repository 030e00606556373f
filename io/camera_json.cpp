#include "io/camera_json.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/input_limits.hpp"
#include "io/camera_model_json.hpp"
#include "io/json_read.hpp"

namespace silva::io {

namespace {

/// The "lighting" object of a camera file.
nlohmann::ordered_json lighting_json(const LightingRecord& l) {
  nlohmann::ordered_json j;
  j["time_of_day"] = l.time_of_day;
  j["weather"] = l.weather;
  j["randomized"] = l.randomized;
  j["sun_elevation_deg"] = l.sun_elevation_deg;
  j["sun_azimuth_deg"] = l.sun_azimuth_deg;
  j["cloud_cover"] = l.cloud_cover;
  j["fog_density_scale"] = l.fog_density_scale;
  j["white_balance_k"] = l.white_balance_k;
  j["exposure"] = l.exposure;
  j["exposure_compensation_ev"] = l.exposure_compensation_ev;
  j["ev100"] = l.ev100 ? nlohmann::ordered_json(*l.ev100) : nlohmann::ordered_json(nullptr);
  return j;
}

/// Parses lighting_json's object; `where` names it in InputError messages.
LightingRecord parse_lighting(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object()) throw InputError(where + " must be an object");
  LightingRecord l;
  l.time_of_day = json_string(j, "time_of_day", where);
  l.weather = json_string(j, "weather", where);
  const nlohmann::json& randomized = json_member(j, "randomized", where);
  if (!randomized.is_boolean()) throw InputError(where + ": 'randomized' must be true or false");
  l.randomized = randomized.get<bool>();
  l.sun_elevation_deg = json_number(j, "sun_elevation_deg", where);
  l.sun_azimuth_deg = json_number(j, "sun_azimuth_deg", where);
  l.cloud_cover = json_number(j, "cloud_cover", where);
  l.fog_density_scale = json_number(j, "fog_density_scale", where);
  l.white_balance_k = json_number(j, "white_balance_k", where);
  l.exposure = json_string(j, "exposure", where);
  if (l.exposure != "preset" && l.exposure != "auto")
    throw InputError(where + ": 'exposure' must be \"preset\" or \"auto\", got \"" + l.exposure + "\"");
  l.exposure_compensation_ev = json_number(j, "exposure_compensation_ev", where);
  if (!json_member(j, "ev100", where).is_null()) l.ev100 = json_number(j, "ev100", where);
  return l;
}

}  // namespace

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
  if (r.lighting) j["lighting"] = lighting_json(*r.lighting);
  if (r.stereo) j["stereo"] = {{"camera", r.stereo->right ? "right" : "left"}, {"baseline_m", r.stereo->baseline_m}};
  return j.dump(2) + "\n";
}

namespace {

/// InputError naming `source` and `key` unless `ok`.
void require(bool ok, const std::string& source, const std::string& key, const std::string& what) {
  if (!ok) throw InputError(source + ": '" + key + "' " + what);
}

/// The contract's camera: K = [[fx, 0, cx], [0, fy, cy], [0, 0, 1]] with finite fx, fy > 0 and the principal point
/// within an image size of the image; camera_to_world a rigid transform (rotation within 1e-5, last row 0 0 0 1)
/// inside the pose file's world limits; 0 < near < far, finite. Readers project with these, so a damaged file must
/// stop here rather than in a ray caster's assertion or an overflow.
void check_camera(const Camera& c, const std::vector<std::vector<double>>& k, const std::string& source) {
  require(k[0][1] == 0 && k[1][0] == 0 && k[2][0] == 0 && k[2][1] == 0 && k[2][2] == 1, source, "K",
          "must be [[fx, 0, cx], [0, fy, cy], [0, 0, 1]]");
  require(std::isfinite(c.fx) && std::isfinite(c.fy) && c.fx >= 1e-3 && c.fy >= 1e-3 && c.fx <= 1e7 && c.fy <= 1e7,
          source, "K", "needs focal lengths fx, fy in 0.001 ... 1e7 pixels");
  require(std::abs(c.cx - 0.5 * c.width) <= 1.5 * c.width && std::abs(c.cy - 0.5 * c.height) <= 1.5 * c.height,
          source, "K", "needs the principal point (cx, cy) within one image size of the image");
  const Mat4d& m = c.camera_to_world;
  require(m.allFinite() && m(3, 0) == 0 && m(3, 1) == 0 && m(3, 2) == 0 && m(3, 3) == 1, source, "camera_to_world",
          "must be a finite rigid transform with last row 0 0 0 1");
  const Mat3d r = m.block<3, 3>(0, 0);
  require((r.transpose() * r - Mat3d::Identity()).cwiseAbs().maxCoeff() <= 1e-5 && r.determinant() > 0, source,
          "camera_to_world", "needs a rotation (|R^T R - I| <= 1e-5, det +1) in its upper-left 3x3");
  require(std::max(std::abs(m(0, 3)), std::abs(m(1, 3))) <= limits::kMaxPoseCoordinate && std::abs(m(2, 3)) <= limits::kMaxPoseHeight,
          source, "camera_to_world", "puts the camera outside the world (|x|, |y| <= 100000 m, |z| <= 10000 m)");
  require(std::isfinite(c.near) && std::isfinite(c.far) && c.near > 0 && c.far > c.near, source, "near",
          "and 'far' need 0 < near < far, finite");
}

/// The "stereo" object: camera "left" or "right", baseline_m in 0.01 ... 2 metres (config rig.baseline_m's range).
StereoRecord parse_stereo(const nlohmann::json& j, const std::string& source) {
  StereoRecord r;
  const std::string camera = json_string(j, "camera", source);
  if (camera != "left" && camera != "right")
    throw InputError(source + ": 'camera' must be \"left\" or \"right\", got \"" + camera + "\"");
  r.right = camera == "right";
  r.baseline_m = json_number(j, "baseline_m", source);
  if (!(r.baseline_m >= 0.01 && r.baseline_m <= 2))
    throw InputError(source + ": 'baseline_m' must be 0.01 ... 2 metres");
  return r;
}

}  // namespace

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
  c.width = int(json_int(j, "width", 1, 8192, source));
  c.height = int(json_int(j, "height", 1, 8192, source));
  const auto k = json_matrix(j, "K", 3, 3, source);
  c.fx = k[0][0];
  c.fy = k[1][1];
  c.cx = k[0][2];
  c.cy = k[1][2];
  c.camera_to_world = read_matrix4(j, "camera_to_world", source);
  c.near = json_number(j, "near", source);
  c.far = json_number(j, "far", source);
  check_camera(c, k, source);
  r.yaw_deg = json_number(j, "yaw_deg", source);
  r.pitch_deg = json_number(j, "pitch_deg", source);
  r.roll_deg = json_number(j, "roll_deg", source);
  if (!json_member(j, "trail_s", source).is_null()) r.trail_s = json_number(j, "trail_s", source);
  r.model = parse_camera_model(j, source);
  if (j.contains("lighting")) r.lighting = parse_lighting(json_member(j, "lighting", source), source + ": lighting");
  if (j.contains("stereo")) r.stereo = parse_stereo(json_member(j, "stereo", source), source + ": stereo");
  return r;
}

CameraRecord read_camera_json(const std::filesystem::path& path) {
  return parse_camera_json(read_text_file(path), path.string());
}

}  // namespace silva::io
