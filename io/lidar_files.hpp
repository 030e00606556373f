#pragma once
/// @file LiDAR files in the KITTI / SemanticKITTI layouts (CONTRACT.md "LiDAR"): scans, labels with
/// their instance table, and a sequence's calib.txt and poses.txt.
#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "core/camera.hpp"
#include "core/lidar_point.hpp"
#include "core/ontology.hpp"

namespace silva::io {

/// A KITTI velodyne scan: per point float32 x, y, z, intensity, little-endian, no header.
std::vector<uint8_t> kitti_scan(std::span<const LidarPoint> points);

/// Reads a KITTI scan file: per point x, y, z (sensor frame) and intensity. InputError naming the file when it
/// is missing, unreadable, too large or not a whole number of 16-byte points.
std::vector<std::array<float, 4>> read_kitti_scan_xyzi(const std::filesystem::path& path);

/// The x, y, z of read_kitti_scan_xyzi (intensities dropped); errors as that.
std::vector<Vec3f> read_kitti_scan(const std::filesystem::path& path);

/// Reads a SemanticKITTI .label file: one uint32 per point. InputError as read_kitti_scan.
std::vector<uint32_t> read_semantic_kitti_labels(const std::filesystem::path& path);

/// A scan's SemanticKITTI labels and the table of the instances they number.
struct LidarLabels {
  std::vector<uint8_t> labels;  ///< Per point uint32 little-endian: class id | instance << 16.
  std::string instances_json;   ///< {"instances": [{index, instance_id, class_id}]}, as the instance images.
};

/// Labels of `points`: the low 16 bits hold the ontology's class id of the point's role, the high 16
/// bits the scan's instance number: 1, 2, ... for the packed instance ids seen, in ascending order (0 = none).
LidarLabels semantic_kitti_labels(std::span<const LidarPoint> points, const Ontology& ontology);

/// A KITTI calib.txt: P0..P3 (all four the capture camera's 3x4 projection K [I | 0], its pixel
/// centres at integer coordinates) and Tr (the LiDAR frame to the camera frame, 3x4).
std::string kitti_calib(const Camera& camera, const Mat4d& sensor_to_camera);

/// A KITTI poses.txt: one line per pose, the 3x4 row-major transform of camera i to camera 0's frame.
std::string kitti_poses(std::span<const Mat4d> camera_to_world);

/// InputError naming `path` unless it is a calib.txt of kitti_calib's form: lines P0:, P1:, P2:, P3: and Tr:, in
/// that order, each with 12 finite numbers.
void check_kitti_calib(const std::filesystem::path& path);

/// InputError naming `path` unless it is a poses.txt of kitti_poses's form with `frames` lines of 12 finite numbers.
void check_kitti_poses(const std::filesystem::path& path, size_t frames);

}  // namespace silva::io
