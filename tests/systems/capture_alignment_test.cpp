// Outputs of one capture are pixel-aligned: rendered once, encoded to files, decoded with OpenCV,
// the class, instance and depth images of a constructed scene change at exactly the same pixels.
#include <gtest/gtest.h>

#include "systems/write_dataset.hpp"

#include <cmath>
#include <map>
#include <opencv2/imgcodecs.hpp>

#include "../render/raster_test_scenes.hpp"
#include "io/capture_set.hpp"
#include "render/renderer.hpp"

namespace silva {
namespace {

/// Decodes every image of an encoded capture set by its relative path.
std::map<std::string, cv::Mat> decode(const io::EncodedSet& set) {
  std::map<std::string, cv::Mat> out;
  for (const io::EncodedFile& f : set) {
    if (!f.relative_path.ends_with(".png")) continue;
    const std::vector<uint8_t> bytes(f.bytes.begin(), f.bytes.end());
    out[f.relative_path.substr(0, f.relative_path.find('/'))] = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
  }
  return out;
}

TEST(CaptureAlignment, ClassInstanceAndDepthEdgesCoincide) {
  // A camera 1.5 m up looking along +X at a ground plane ending in a wall 30 m ahead, and a 1 m-radius
  // trunk floating from 1 m to 30 m up, 10 m ahead. Ground and wall have constant depth along an image
  // row; every horizontal class edge is a trunk silhouette with the background >= 15 m behind it.
  render::test::OwnedScene s;
  const uint32_t ground = s.add_mesh(render::test::make_quad(Vec3f(-50, -50, 0), Vec3f(30, -50, 0), Vec3f(30, 50, 0),
                                                             Vec3f(-50, 50, 0), Role::Ground));
  const uint32_t wall = s.add_mesh(render::test::make_quad(Vec3f(30, 50, 0), Vec3f(30, -50, 0), Vec3f(30, -50, 60),
                                                           Vec3f(30, 50, 60), Role::Obstacle, /*double_sided=*/true));
  const uint32_t trunk = s.add_mesh(render::test::make_cylinder(1.0f, 1.0f, 30.0f, 48, Role::TreeTrunk));
  s.add_instance(ground);
  s.add_instance(wall);
  s.add_instance(trunk, render::test::place(Vec3f(10, 0, 0)), /*id=*/0x01020003u);
  Camera cam = Camera::from_fov(160, 120, 90.0, 0.05, 150.0);
  cam.camera_to_world = pose_from_angles(Vec3d(0, 0, 1.5), 0, 0, 0);

  render::Renderer renderer;
  render::GBuffer g;
  render::RenderOptions options;
  options.lod = false;
  renderer.render_gbuffer(s.scene, cam, options, g);
  io::OutputSelection outputs;
  for (io::OutputType t : {io::OutputType::Semantic, io::OutputType::Instance, io::OutputType::Depth})
    outputs.enabled[size_t(t)] = true;
  auto images = decode(io::encode_capture_set(systems::label_planes(g), {}, default_ontology(), outputs, 0, false));
  const cv::Mat& semantic = images.at("semantic");
  const cv::Mat& instance = images.at("instance");
  const cv::Mat& depth = images.at("depth");
  ASSERT_EQ(semantic.type(), CV_8UC1);
  ASSERT_EQ(instance.type(), CV_16UC1);
  ASSERT_EQ(depth.type(), CV_16UC1);

  int class_edges = 0;
  for (int y = 0; y < 120; ++y) {
    for (int x = 0; x < 160; ++x) {
      const uint8_t c = semantic.at<uint8_t>(y, x);
      const uint16_t d = depth.at<uint16_t>(y, x);
      EXPECT_EQ(c == 0, d == 0) << "sky class and no-hit depth must coincide at " << x << "," << y;
      EXPECT_EQ(c == uint8_t(Role::TreeTrunk), instance.at<uint16_t>(y, x) != 0) << x << "," << y;
      if (x + 1 == 160) continue;
      const uint8_t c2 = semantic.at<uint8_t>(y, x + 1);
      const int jump = std::abs(int(d) - int(depth.at<uint16_t>(y, x + 1)));
      if (c != c2) {
        ++class_edges;
        EXPECT_GT(jump, 1000) << "class edge without a depth discontinuity at " << x << "," << y;
      } else if (c != uint8_t(Role::TreeTrunk)) {
        EXPECT_LE(jump, 1) << "depth jump inside one ground or wall row at " << x << "," << y;
      }
    }
  }
  EXPECT_GT(class_edges, 2 * 60);  // both trunk silhouettes cross the top 64 rows
}

}  // namespace
}  // namespace silva
