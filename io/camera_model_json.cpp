#include "io/camera_model_json.hpp"

#include "core/error.hpp"
#include "io/json_read.hpp"

namespace silva::io {

namespace {

/// The member `key` of `obj` as an object, or nullptr when it is null; InputError otherwise.
const nlohmann::json* optional_object(const nlohmann::json& obj, const std::string& key, const std::string& where) {
  const nlohmann::json& v = json_member(obj, key, where);
  if (v.is_null()) return nullptr;
  if (!v.is_object()) throw InputError(where + ": 'camera_model." + key + "' must be an object or null");
  return &v;
}

}  // namespace

nlohmann::ordered_json matrix4_json(const Mat4d& m) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (int row = 0; row < 4; ++row) rows.push_back({m(row, 0), m(row, 1), m(row, 2), m(row, 3)});
  return rows;
}

Mat4d read_matrix4(const nlohmann::json& obj, const std::string& key, const std::string& where) {
  const auto m = json_matrix(obj, key, 4, 4, where);
  Mat4d out;
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) out(row, col) = m[size_t(row)][size_t(col)];
  return out;
}

nlohmann::ordered_json camera_model_json(const CameraModel& model) {
  nlohmann::ordered_json j;
  j["noise"] = nullptr;
  if (const auto& n = model.noise)
    j["noise"] = {{"full_well_e", n->full_well_e}, {"read_noise_e", n->read_noise_e}, {"gain", n->gain},
                  {"max_gain", n->max_gain}};
  j["vignetting"] = model.vignetting;
  j["chromatic_aberration"] = model.chromatic_aberration;
  j["bloom"] = model.bloom;
  j["chroma"] = model.chroma;
  j["jpeg_quality"] = model.jpeg_quality;
  j["depth_of_field"] = nullptr;
  if (const auto& d = model.depth_of_field)
    j["depth_of_field"] = {
        {"f_number", d->f_number}, {"focus_distance", d->focus_distance}, {"focal_length_mm", d->focal_length_mm}};
  j["motion_blur"] = nullptr;
  if (const auto& m = model.motion)
    j["motion_blur"] = {{"shutter_s", m->shutter_s},
                        {"open_camera_to_world", matrix4_json(m->open_to_world)},
                        {"close_camera_to_world", matrix4_json(m->close_to_world)}};
  return j;
}

CameraModel parse_camera_model(const nlohmann::json& obj, const std::string& where) {
  const nlohmann::json& j = json_member(obj, "camera_model", where);
  if (!j.is_object()) throw InputError(where + ": 'camera_model' must be an object");
  CameraModel m;
  if (const nlohmann::json* n = optional_object(j, "noise", where)) {
    const double gain = json_number(*n, "gain", where);
    m.noise = SensorNoise{json_number(*n, "full_well_e", where), json_number(*n, "read_noise_e", where), gain,
                          n->contains("max_gain") ? json_number(*n, "max_gain", where) : gain};
  }
  m.vignetting = json_number(j, "vignetting", where);
  m.chromatic_aberration = json_number(j, "chromatic_aberration", where);
  if (j.contains("bloom")) m.bloom = json_number(j, "bloom", where);
  if (j.contains("chroma")) m.chroma = json_number(j, "chroma", where);
  if (j.contains("jpeg_quality")) m.jpeg_quality = int(json_number(j, "jpeg_quality", where));
  if (const nlohmann::json* d = optional_object(j, "depth_of_field", where))
    m.depth_of_field = DepthOfField{json_number(*d, "f_number", where), json_number(*d, "focus_distance", where),
                                    json_number(*d, "focal_length_mm", where)};
  if (const nlohmann::json* b = optional_object(j, "motion_blur", where))
    m.motion = ExposureMotion{json_number(*b, "shutter_s", where), read_matrix4(*b, "open_camera_to_world", where),
                              read_matrix4(*b, "close_camera_to_world", where)};
  return m;
}

}  // namespace silva::io
