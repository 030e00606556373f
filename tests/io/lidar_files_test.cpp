// Known answers for the KITTI / SemanticKITTI LiDAR files.
#include "io/lidar_files.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <nlohmann/json.hpp>

namespace silva::io {
namespace {

/// Reads the i-th little-endian T of `bytes`.
template <class T>
T at(const std::vector<uint8_t>& bytes, size_t i) {
  T v;
  std::memcpy(&v, bytes.data() + i * sizeof(T), sizeof(T));
  return v;
}

std::vector<LidarPoint> three_points() {
  std::vector<LidarPoint> p(3);
  p[0].position = Vec3f(1.5f, -2.0f, 0.25f);
  p[0].intensity = 0.5f;
  p[0].role = Role::Ground;
  p[1].position = Vec3f(3, 4, 5);
  p[1].intensity = 1.0f;
  p[1].role = Role::TreeTrunk;
  p[1].instance_id = 0x05060010u;
  p[2].position = Vec3f(-1, 0, 2);
  p[2].role = Role::Obstacle;
  p[2].instance_id = 0x01020003u;
  return p;
}

TEST(LidarFiles, ScanIsFourFloatsPerPoint) {
  const std::vector<uint8_t> scan = kitti_scan(three_points());
  ASSERT_EQ(scan.size(), 3u * 16u);
  EXPECT_EQ(at<float>(scan, 0), 1.5f);
  EXPECT_EQ(at<float>(scan, 1), -2.0f);
  EXPECT_EQ(at<float>(scan, 2), 0.25f);
  EXPECT_EQ(at<float>(scan, 3), 0.5f);
  EXPECT_EQ(at<float>(scan, 6), 5.0f);
  EXPECT_EQ(at<float>(scan, 7), 1.0f);
}

TEST(LidarFiles, LabelsHoldClassLowAndScanInstanceHigh) {
  Ontology o = default_ontology();
  o.classes[uint8_t(Role::TreeTrunk)].id = 30;
  const LidarLabels l = semantic_kitti_labels(three_points(), o);
  ASSERT_EQ(l.labels.size(), 3u * 4u);
  // Instances are numbered in ascending packed id: 0x01020003 -> 1, 0x05060010 -> 2.
  EXPECT_EQ(at<uint32_t>(l.labels, 0), 1u);
  EXPECT_EQ(at<uint32_t>(l.labels, 1), 30u | (2u << 16));
  EXPECT_EQ(at<uint32_t>(l.labels, 2), 9u | (1u << 16));
  const auto table = nlohmann::json::parse(l.instances_json).at("instances");
  ASSERT_EQ(table.size(), 2u);
  EXPECT_EQ(table[0].at("index"), 1);
  EXPECT_EQ(table[0].at("instance_id"), 0x01020003u);
  EXPECT_EQ(table[0].at("class_id"), 9);
  EXPECT_EQ(table[1].at("instance_id"), 0x05060010u);
  EXPECT_EQ(table[1].at("class_id"), 30);
}

TEST(LidarFiles, CalibHoldsProjectionsAndTheLidarToCameraTransform) {
  Camera cam = Camera::from_fov(200, 100, 90.0, 0.05, 100.0);
  Mat4d tr = Mat4d::Identity();
  tr(0, 3) = 0.25;
  const std::string calib = kitti_calib(cam, tr);
  // fx = 100, cx = 100 (pixel centres at x + 0.5) -> 99.5 with centres at integers.
  EXPECT_NE(calib.find("P0: 1.000000000000e+02 0.000000000000e+00 9.950000000000e+01 0.000000000000e+00 "
                       "0.000000000000e+00 1.000000000000e+02 4.950000000000e+01"),
            std::string::npos)
      << calib;
  for (const char* key : {"\nP1: ", "\nP2: ", "\nP3: ", "\nTr: 1.000000000000e+00 0.000000000000e+00 0.000000000000e+00 2.500000000000e-01 "})
    EXPECT_NE(calib.find(key), std::string::npos) << key;
}

TEST(LidarFiles, PosesAreRelativeToTheFirstCamera) {
  Mat4d a = Mat4d::Identity(), b = Mat4d::Identity();
  a.block<3, 1>(0, 3) = Vec3d(10, 20, 1.5);
  b.block<3, 1>(0, 3) = Vec3d(10, 22, 1.5);
  const std::vector<Mat4d> poses = {a, b};
  const std::string text = kitti_poses(poses);
  const auto newline = text.find('\n');
  EXPECT_EQ(text.substr(0, newline),
            "1.000000000000e+00 0.000000000000e+00 0.000000000000e+00 0.000000000000e+00 "
            "0.000000000000e+00 1.000000000000e+00 0.000000000000e+00 0.000000000000e+00 "
            "0.000000000000e+00 0.000000000000e+00 1.000000000000e+00 0.000000000000e+00");
  EXPECT_NE(text.find("1.000000000000e+00 0.000000000000e+00 2.000000000000e+00", newline), std::string::npos) << text;
}

}  // namespace
}  // namespace silva::io
