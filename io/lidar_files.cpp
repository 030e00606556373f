#include "io/lidar_files.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <sstream>

#include "core/error.hpp"
#include "core/input_limits.hpp"
#include "io/label_images.hpp"

namespace silva::io {

namespace {

/// Appends the little-endian bytes of `v` (the host is little-endian: x86-64, aarch64).
template <class T>
void put(std::vector<uint8_t>& out, T v) {
  uint8_t b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  out.insert(out.end(), b, b + sizeof(T));
}

/// The 12 numbers of a 3x4 matrix, row-major, after "name: ".
std::string matrix_line(const char* name, const Eigen::Matrix<double, 3, 4>& m) {
  std::string line = std::string(name) + ":";
  char num[32];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) {
      std::snprintf(num, sizeof num, " %.12e", m(r, c));
      line += num;
    }
  return line + "\n";
}

/// The file's bytes as `n` records of `record` bytes each; InputError unless the size is a whole multiple.
std::string read_records(const std::filesystem::path& path, size_t record, const char* what, size_t& n) {
  std::string bytes = limits::read_input_file(path, what);
  if (bytes.size() % record != 0)
    throw InputError(path.string() + ": " + std::to_string(bytes.size()) + " bytes, not a whole number of " +
                     std::to_string(record) + "-byte records (" + what + ")");
  n = bytes.size() / record;
  return bytes;
}

}  // namespace

std::vector<std::array<float, 4>> read_kitti_scan_xyzi(const std::filesystem::path& path) {
  size_t n = 0;
  const std::string bytes = read_records(path, 16, "KITTI scan", n);
  std::vector<std::array<float, 4>> points(n);
  if (n > 0) std::memcpy(points.data(), bytes.data(), 16 * n);
  return points;
}

std::vector<Vec3f> read_kitti_scan(const std::filesystem::path& path) {
  const std::vector<std::array<float, 4>> xyzi = read_kitti_scan_xyzi(path);
  std::vector<Vec3f> points(xyzi.size());
  for (size_t i = 0; i < xyzi.size(); ++i) points[i] = Vec3f(xyzi[i][0], xyzi[i][1], xyzi[i][2]);
  return points;
}

std::vector<uint32_t> read_semantic_kitti_labels(const std::filesystem::path& path) {
  size_t n = 0;
  const std::string bytes = read_records(path, 4, "SemanticKITTI labels", n);
  std::vector<uint32_t> labels(n);
  std::memcpy(labels.data(), bytes.data(), 4 * n);
  return labels;
}

std::vector<uint8_t> kitti_scan(std::span<const LidarPoint> points) {
  std::vector<uint8_t> out;
  out.reserve(points.size() * 16);
  for (const LidarPoint& p : points) {
    put(out, p.position.x());
    put(out, p.position.y());
    put(out, p.position.z());
    put(out, p.intensity);
  }
  return out;
}

LidarLabels semantic_kitti_labels(std::span<const LidarPoint> points, const Ontology& ontology) {
  std::map<uint32_t, InstanceEntry> seen;  // packed id -> entry (index filled below)
  for (const LidarPoint& p : points)
    if (p.instance_id != 0) seen.emplace(p.instance_id, InstanceEntry{0, p.instance_id, ontology.id(p.role)});
  std::vector<InstanceEntry> entries;
  for (auto& [id, e] : seen) {
    e.index = uint16_t(entries.size() + 1);
    entries.push_back(e);
  }
  LidarLabels out;
  out.labels.reserve(points.size() * 4);
  for (const LidarPoint& p : points) {
    const uint32_t instance = p.instance_id ? seen.at(p.instance_id).index : 0;
    put(out.labels, uint32_t(ontology.id(p.role)) | (instance << 16));
  }
  out.instances_json = instance_table_json(entries);
  return out;
}

std::string kitti_calib(const Camera& camera, const Mat4d& sensor_to_camera) {
  Eigen::Matrix<double, 3, 4> p = Eigen::Matrix<double, 3, 4>::Zero();
  p(0, 0) = camera.fx;
  p(1, 1) = camera.fy;
  p(0, 2) = camera.cx - 0.5;
  p(1, 2) = camera.cy - 0.5;
  p(2, 2) = 1.0;
  std::string out;
  for (const char* name : {"P0", "P1", "P2", "P3"}) out += matrix_line(name, p);
  out += matrix_line("Tr", sensor_to_camera.topRows<3>());
  return out;
}

std::string kitti_poses(std::span<const Mat4d> camera_to_world) {
  std::string out;
  if (camera_to_world.empty()) return out;
  const Mat4d world_to_first = camera_to_world[0].inverse();
  for (const Mat4d& pose : camera_to_world) {
    const std::string line = matrix_line("x", (world_to_first * pose).topRows<3>());
    out += line.substr(3);  // drop "x: "
  }
  return out;
}

namespace {

/// The lines of a KITTI text file, each "[<key>: ]" and 12 finite numbers; InputError naming `path` and the line.
std::vector<std::string> kitti_rows(const std::filesystem::path& path, bool keyed) {
  std::istringstream in(limits::read_input_file(path, "KITTI file"));
  std::vector<std::string> keys;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string key;
    if (keyed) row >> key;
    int count = 0;
    double v = 0;
    while (row >> v) {
      if (!std::isfinite(v)) break;
      ++count;
    }
    if (count != 12 || !row.eof())
      throw InputError(path.string() + ": line " + std::to_string(keys.size() + 1) +
                       " is not 12 finite numbers" + (keyed ? " after its key" : ""));
    keys.push_back(key);
  }
  return keys;
}

}  // namespace

void check_kitti_calib(const std::filesystem::path& path) {
  if (kitti_rows(path, true) != std::vector<std::string>{"P0:", "P1:", "P2:", "P3:", "Tr:"})
    throw InputError(path.string() + ": not a KITTI calib.txt (lines P0:, P1:, P2:, P3:, Tr:)");
}

void check_kitti_poses(const std::filesystem::path& path, size_t frames) {
  const size_t rows = kitti_rows(path, false).size();
  if (rows != frames)
    throw InputError(path.string() + ": " + std::to_string(rows) + " poses for the sequence's " +
                     std::to_string(frames) + " frames");
}

}  // namespace silva::io
