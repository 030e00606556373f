#include "io/capture_set.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>

#include "io/label_images.hpp"
#include "io_test_util.hpp"

namespace silva::io {
namespace {

std::vector<uint8_t> grainy_rgb(int w, int h) {
  std::vector<uint8_t> rgb(size_t(w) * h * 3);
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = uint8_t((i * 7 + (i * i) % 13) & 0xff);
  return rgb;
}

/// Writes a set under dir and reads every file back by relative path.
std::map<std::string, cv::Mat> write_and_read_set(const std::filesystem::path& dir, const EncodedSet& set) {
  std::map<std::string, cv::Mat> images;
  for (const EncodedFile& f : set) {
    std::filesystem::create_directories(dir / f.relative_path.substr(0, f.relative_path.find('/')));
    if (f.relative_path.ends_with(".json"))
      write_file_atomic(dir / f.relative_path, f.bytes);
    else
      images[f.relative_path] = test::write_and_read(dir, f.relative_path, f.bytes);
  }
  return images;
}

TEST(CaptureSet, FileNamesFollowTheLayout) {
  const auto g = test::synthetic_gbuffer();
  const auto set = encode_capture_set(g, grainy_rgb(g.width, g.height), default_ontology(), OutputSelection::all(), 42, false);
  std::vector<std::string> names;
  for (const auto& f : set) names.push_back(f.relative_path);
  EXPECT_EQ(names, (std::vector<std::string>{"rgb/000042.png", "semantic/000042.png", "semantic_color/000042.png",
                                             "instance/000042.png", "instance/000042.json", "depth/000042.png",
                                             "depth_exr/000042.exr", "depth_preview/000042.png", "normal/000042.png"}));
  EXPECT_EQ(frame_file("camera", 7, "json"), "camera/000007.json");
}

TEST(CaptureSet, EveryOutputRoundTripsThroughOpenCv) {
  const auto dir = test::scratch_dir("capture_set_roundtrip");
  const auto g = test::synthetic_gbuffer();
  const auto rgb = grainy_rgb(g.width, g.height);
  const Ontology o = default_ontology();
  const auto set = encode_capture_set(g, rgb, o, OutputSelection::all(), 3, false);
  auto img = write_and_read_set(dir, set);
  const cv::Mat& c = img["rgb/000003.png"];
  const cv::Mat& sem = img["semantic/000003.png"];
  const cv::Mat& semc = img["semantic_color/000003.png"];
  const cv::Mat& inst = img["instance/000003.png"];
  const cv::Mat& depth = img["depth/000003.png"];
  const cv::Mat& exr = img["depth_exr/000003.exr"];
  const cv::Mat& prev = img["depth_preview/000003.png"];
  const cv::Mat& nrm = img["normal/000003.png"];
  ASSERT_EQ(c.type(), CV_8UC3);
  ASSERT_EQ(sem.type(), CV_8UC1);
  ASSERT_EQ(semc.type(), CV_8UC3);
  ASSERT_EQ(inst.type(), CV_16UC1);
  ASSERT_EQ(depth.type(), CV_16UC1);
  ASSERT_EQ(exr.type(), CV_32FC1);
  ASSERT_EQ(prev.type(), CV_8UC1);
  ASSERT_EQ(nrm.type(), CV_8UC3);
  const auto table = nlohmann::json::parse(test::file_bytes(dir / "instance/000003.json")).at("instances");
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      const size_t i = size_t(y) * g.width + x;
      const float z = g.depth[i];
      for (int a = 0; a < 3; ++a) ASSERT_EQ(c.at<cv::Vec3b>(y, x)[2 - a], rgb[3 * i + a]);
      ASSERT_EQ(sem.at<uint8_t>(y, x), o.id(g.role[i]));
      // semantic_color is the palette lookup of the id image
      const auto& pal = o.classes[sem.at<uint8_t>(y, x)].color;
      for (int a = 0; a < 3; ++a) ASSERT_EQ(semc.at<cv::Vec3b>(y, x)[2 - a], pal[a]);
      const uint16_t mm = depth.at<uint16_t>(y, x);
      if (z > 0) {
        ASSERT_LE(std::abs(double(mm) - std::min(65535.0, double(z) * 1000.0)), 1.0) << z;
        ASSERT_GE(mm, 1);
      } else {
        ASSERT_EQ(mm, 0);
      }
      ASSERT_EQ(exr.at<float>(y, x), z);
      ASSERT_EQ(prev.at<uint8_t>(y, x), depth_to_preview(z));
      for (int a = 0; a < 3; ++a)
        ASSERT_EQ(nrm.at<cv::Vec3b>(y, x)[2 - a], z > 0 ? normal_to_byte(g.normal[i][a]) : 0);
      const uint16_t idx = inst.at<uint16_t>(y, x);
      if (idx) {
        ASSERT_LE(idx, table.size());
        ASSERT_EQ(table[idx - 1]["index"], idx);
        ASSERT_EQ(table[idx - 1]["instance_id"], g.instance_id[i]);
        ASSERT_EQ(table[idx - 1]["class_id"], sem.at<uint8_t>(y, x));
      }
    }
}

TEST(CaptureSet, BytesIdenticalAcrossEncodesAndThreadCounts) {
  const auto g = test::synthetic_gbuffer(211, 97);
  const auto rgb = grainy_rgb(g.width, g.height);
  auto encode_with = [&](int threads) {
    tbb::task_arena arena(threads);
    EncodedSet set;
    arena.execute([&] { set = encode_capture_set(g, rgb, default_ontology(), OutputSelection::all(), 0, false); });
    return set;
  };
  const EncodedSet a = encode_with(1), b = encode_with(2), c = encode_with(2);
  ASSERT_EQ(a.size(), b.size());
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].relative_path, b[k].relative_path);
    EXPECT_EQ(a[k].bytes, b[k].bytes) << a[k].relative_path;
    EXPECT_EQ(b[k].bytes, c[k].bytes) << a[k].relative_path;
  }
}

TEST(CaptureSet, OnlySelectedOutputsAndNoRgbNeeded) {
  const auto g = test::synthetic_gbuffer();
  const auto set = encode_capture_set(g, {}, default_ontology(), OutputSelection::from_names({"depth_preview", "semantic"}), 1, false);
  ASSERT_EQ(set.size(), 2u);
  EXPECT_EQ(set[0].relative_path, "semantic/000001.png");
  EXPECT_EQ(set[1].relative_path, "depth_preview/000001.png");
}

TEST(CaptureSet, RightCameraWritesIntoItsOwnFolders) {
  const auto g = test::synthetic_gbuffer();
  const auto set = encode_capture_set(g, {}, default_ontology(), OutputSelection::from_names({"semantic", "instance"}), 5, true);
  std::vector<std::string> names;
  for (const auto& f : set) names.push_back(f.relative_path);
  EXPECT_EQ(names, (std::vector<std::string>{"semantic_right/000005.png", "instance_right/000005.png",
                                             "instance_right/000005.json"}));
}

TEST(CaptureSet, FrameFileNamesListEveryFileOfAFrame) {
  const OutputSelection sel = OutputSelection::from_names({"rgb", "depth_exr", "lidar"});
  EXPECT_EQ(frame_file_names(sel, 2, false),
            (std::vector<std::string>{"rgb/000002.png", "depth_exr/000002.exr", "lidar/000002.bin",
                                      "lidar_labels/000002.label", "lidar_labels/000002.json"}));
  EXPECT_EQ(frame_file_names(OutputSelection::from_names({"rgb"}), 2, true),
            (std::vector<std::string>{"rgb/000002.png", "rgb_right/000002.png", "camera_right/000002.json",
                                      "disparity/000002.png"}));
}

}  // namespace
}  // namespace silva::io
