#include "io/pose_file.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/camera.hpp"
#include "core/error.hpp"
#include "core/input_limits.hpp"
#include "io/json_read.hpp"

namespace silva::io {

namespace {

/// Refuses a position outside the world Silva can build exactly (limits::kMaxPoseCoordinate).
void check_position(const Vec3d& position, const std::string& where) {
  const double xy = std::max(std::abs(position.x()), std::abs(position.y()));
  if (xy > limits::kMaxPoseCoordinate || std::abs(position.z()) > limits::kMaxPoseHeight)
    throw InputError(where + ": position (" + std::to_string(position.x()) + ", " + std::to_string(position.y()) +
                     ", " + std::to_string(position.z()) + ") is out of range (|x|, |y| <= " +
                     std::to_string(int(limits::kMaxPoseCoordinate)) + " m, |z| <= " +
                     std::to_string(int(limits::kMaxPoseHeight)) + " m)");
}

PoseEntry pose_from_angles_entry(const Vec3d& position, bool has_z, double yaw, double pitch, double roll,
                                 const std::string& where) {
  check_position(position, where);
  PoseEntry p;
  p.position = position;
  p.has_z = has_z;
  p.yaw_deg = yaw;
  p.pitch_deg = pitch;
  p.roll_deg = roll;
  p.rotation = rotation_from_angles(yaw, pitch, roll);
  return p;
}

PoseEntry pose_from_matrix(const nlohmann::json& e, const std::string& where) {
  const auto m = json_matrix(e, "camera_to_world", 4, 4, where);
  PoseEntry p;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) p.rotation(r, c) = m[r][c];
    p.position[r] = m[r][3];
  }
  check_position(p.position, where);
  const double bottom = std::max({std::abs(m[3][0]), std::abs(m[3][1]), std::abs(m[3][2]), std::abs(m[3][3] - 1.0)});
  if (bottom > kOrthonormalTolerance)
    throw InputError(where + ": 'camera_to_world' bottom row must be [0, 0, 0, 1]");
  const double err = (p.rotation.transpose() * p.rotation - Mat3d::Identity()).cwiseAbs().maxCoeff();
  if (err > kOrthonormalTolerance)
    throw InputError(where + ": 'camera_to_world' rotation is not orthonormal (|R^T R - I| = " + std::to_string(err) +
                     ", allowed <= 1e-5)");
  if (p.rotation.determinant() < 0)
    throw InputError(where + ": 'camera_to_world' rotation is a reflection (determinant < 0); a rotation is required");
  const Vec3d a = angles_from_rotation(p.rotation);
  p.yaw_deg = a.x();
  p.pitch_deg = a.y();
  p.roll_deg = a.z();
  return p;
}

PoseEntry pose_from_json(const nlohmann::json& e, const std::string& where) {
  if (!e.is_object()) throw InputError(where + ": must be an object with \"position\" + angles or \"camera_to_world\"");
  const bool has_matrix = e.contains("camera_to_world"), has_position = e.contains("position");
  if (has_matrix == has_position)
    throw InputError(where + ": needs exactly one of \"position\" (with yaw_deg, pitch_deg, roll_deg) or "
                     "\"camera_to_world\"");
  // A key this format does not know would be silently ignored: refuse it.
  const std::vector<std::string> allowed =
      has_matrix ? std::vector<std::string>{"camera_to_world"}
                 : std::vector<std::string>{"position", "yaw_deg", "pitch_deg", "roll_deg"};
  for (const auto& item : e.items()) {
    if (std::find(allowed.begin(), allowed.end(), item.key()) != allowed.end()) continue;
    std::string list;
    for (const std::string& k : allowed) list += (list.empty() ? "" : ", ") + k;
    throw InputError(where + ": unknown key \"" + item.key() + "\" (allowed with it: " + list + ")");
  }
  if (has_matrix) return pose_from_matrix(e, where);
  const nlohmann::json& pos = e["position"];
  const bool shape_ok = pos.is_array() && (pos.size() == 2 || pos.size() == 3) &&
                        std::all_of(pos.begin(), pos.end(), [](const nlohmann::json& v) {
                          return v.is_number() && std::isfinite(v.get<double>());
                        });
  if (!shape_ok)
    throw InputError(where + ": 'position' must be [x, y, z] or [x, y] of numbers, got " +
                     limits::quoted_prefix(pos.dump()));
  const Vec3d position(pos[0].get<double>(), pos[1].get<double>(), pos.size() == 3 ? pos[2].get<double>() : 0.0);
  return pose_from_angles_entry(position, pos.size() == 3, json_number(e, "yaw_deg", where),
                                json_number(e, "pitch_deg", where), json_number(e, "roll_deg", where), where);
}

std::string trim(const std::string& s) {
  size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream ss(line);
  std::string f;
  while (std::getline(ss, f, ',')) fields.push_back(trim(f));
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

/// Parses a whole field as a finite number; false if it is not one.
bool parse_number(const std::string& s, double& out) {
  if (s.empty()) return false;
  const char* begin = s.data() + (s[0] == '+' ? 1 : 0);
  const auto [end, ec] = std::from_chars(begin, s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size() && std::isfinite(out);
}

void require_poses(const std::vector<PoseEntry>& poses, const std::string& source) {
  if (poses.empty()) throw InputError(source + ": holds no poses; the custom sequence needs at least one");
}

/// Refuses a pose file with more poses than frame files can number.
void check_pose_count(size_t count, const std::string& source) {
  if (count > size_t(limits::kMaxFramesPerSequence))
    throw InputError(source + ": more than " + std::to_string(limits::kMaxFramesPerSequence) +
                     " poses (frame files are numbered with six digits)");
}

constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

}  // namespace

std::vector<PoseEntry> parse_pose_json(const std::string& text, const std::string& source) {
  const nlohmann::json j = parse_json_text(text, source);
  const nlohmann::json& list = json_member(j, "poses", source);
  if (!list.is_array()) throw InputError(source + ": 'poses' must be a list");
  check_pose_count(list.size(), source);
  std::vector<PoseEntry> poses;
  for (size_t k = 0; k < list.size(); ++k) poses.push_back(pose_from_json(list[k], source + ": pose " + std::to_string(k)));
  require_poses(poses, source);
  return poses;
}

std::vector<PoseEntry> parse_pose_csv(const std::string& text, const std::string& source) {
  static const char* kHeader = "x,y,z,yaw_deg,pitch_deg,roll_deg";
  static const char* kColumns[6] = {"x", "y", "z", "yaw_deg", "pitch_deg", "roll_deg"};
  // UTF-16 (a spreadsheet's "Unicode text") or binary data: say so rather than quote bytes cut at the first NUL.
  if (text.starts_with("\xFF\xFE") || text.starts_with("\xFE\xFF") || text.find('\0') != std::string::npos)
    throw InputError(source + ": not UTF-8 text (UTF-16 or binary: it holds NUL bytes); save the CSV as UTF-8");
  // A byte-order mark (spreadsheet exports write one) is not part of the header.
  std::stringstream in(std::string(text.starts_with(kUtf8Bom) ? text.substr(kUtf8Bom.size()) : text));
  std::string line;
  std::vector<PoseEntry> poses;
  bool header_seen = false;
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    if (trim(line).empty()) continue;
    const std::vector<std::string> fields = split_commas(line);
    if (!header_seen) {
      std::string joined;
      for (size_t i = 0; i < fields.size(); ++i) joined += (i ? "," : "") + fields[i];
      if (joined != kHeader)
        throw InputError(source + ": line " + std::to_string(line_no) + ": header must be \"" + kHeader + "\", got \"" +
                         trim(line) + "\"");
      header_seen = true;
      continue;
    }
    const std::string where = source + ": line " + std::to_string(line_no) + " (pose " + std::to_string(poses.size()) + ")";
    if (fields.size() != 6)
      throw InputError(where + ": expected 6 comma-separated values (" + kHeader + "), got " + std::to_string(fields.size()));
    double v[6] = {};
    for (int c = 0; c < 6; ++c) {
      if (c == 2 && fields[c].empty()) continue;  // z omitted
      if (!parse_number(fields[c], v[c]))
        throw InputError(where + ": '" + kColumns[c] + "' must be a number, got \"" + fields[c] + "\"");
    }
    check_pose_count(poses.size() + 1, source);
    poses.push_back(pose_from_angles_entry(Vec3d(v[0], v[1], v[2]), !fields[2].empty(), v[3], v[4], v[5], where));
  }
  if (!header_seen) throw InputError(source + ": empty; the first line must be \"" + std::string(kHeader) + "\"");
  require_poses(poses, source);
  return poses;
}

std::vector<PoseEntry> read_pose_file(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
  const std::string text = read_text_file(path);
  return ext == ".csv" ? parse_pose_csv(text, path.string()) : parse_pose_json(text, path.string());
}

}  // namespace silva::io
