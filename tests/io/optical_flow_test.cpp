// Exact optical flow: analytic fields for translations over a wall and for rotations, occlusion and sky,
// and the KITTI / Middlebury encodings read back with OpenCV and by hand.
#include "io/optical_flow.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include <opencv2/imgcodecs.hpp>

namespace silva::io {
namespace {

/// A 64x48 camera with a 90 degree field of view looking along +x of the world, moved by `motion` in its own axes.
Camera camera(const Mat4d& motion = Mat4d::Identity()) {
  Camera c = Camera::from_fov(64, 48, 90.0, 0.05, 150.0);
  c.camera_to_world = pose_from_angles(Vec3d(0, 0, 1.5), 0, 0, 0) * motion;
  return c;
}

/// A rigid motion in camera axes: turn by `yaw_deg` about the camera's y axis, then move by `t`.
Mat4d motion(const Vec3d& t, double yaw_deg = 0) {
  Mat4d m = Mat4d::Identity();
  m.block<3, 3>(0, 0) = Eigen::AngleAxisd(yaw_deg * 3.14159265358979323846 / 180.0, Vec3d::UnitY()).toRotationMatrix();
  m.block<3, 1>(0, 3) = t;
  return m;
}

cv::Mat wall(double z) { return cv::Mat(48, 64, CV_32FC1, cv::Scalar(z)); }

size_t at(int x, int y) { return size_t(y) * 64 + size_t(x); }

TEST(OpticalFlow, SidewaysStepOverAWallShiftsEveryPixelByFocalTimesStepOverDepth) {
  const Camera from = camera(), to = camera(motion(Vec3d(0.5, 0, 0)));
  const FlowField flow = optical_flow(from, wall(10), to, wall(10));
  const double shift = -from.fx * 0.5 / 10.0;  // the camera moves right: the scene moves left
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) {
      EXPECT_NEAR(flow.u[at(x, y)], shift, 1e-4);
      EXPECT_NEAR(flow.v[at(x, y)], 0.0, 1e-4);
      EXPECT_EQ(flow.state[at(x, y)], x + 0.5 + shift >= 0 ? FlowState::Valid : FlowState::OutOfView) << x;
    }
}

TEST(OpticalFlow, StepForwardExpandsFromThePrincipalPoint) {
  const Camera from = camera(), to = camera(motion(Vec3d(0, 0, 1)));
  const FlowField flow = optical_flow(from, wall(10), to, wall(9));
  for (int y = 0; y < 48; y += 5)
    for (int x = 0; x < 64; x += 5) {
      // The wall 10 m away is 9 m away after the step: offsets from the principal point grow by 10 / 9.
      EXPECT_NEAR(flow.u[at(x, y)], (x + 0.5 - from.cx) / 9.0, 1e-4);
      EXPECT_NEAR(flow.v[at(x, y)], (y + 0.5 - from.cy) / 9.0, 1e-4);
    }
}

TEST(OpticalFlow, PureRotationIsTheSameForEveryDepth) {
  const Camera from = camera(), to = camera(motion(Vec3d::Zero(), 5.0));
  cv::Mat depth(48, 64, CV_32FC1);
  cv::randu(depth, 1.0, 100.0);
  const FlowField flow = optical_flow(from, depth, to, wall(50));
  const Mat3d r = Eigen::AngleAxisd(5.0 * 3.14159265358979323846 / 180.0, Vec3d::UnitY()).toRotationMatrix();
  for (int y = 0; y < 48; y += 3)
    for (int x = 0; x < 64; x += 3) {
      // The homography K R^T K^-1 of a turn, whatever the depth.
      const Vec3d ray = r.transpose() * Vec3d((x + 0.5 - from.cx) / from.fx, (y + 0.5 - from.cy) / from.fy, 1.0);
      EXPECT_NEAR(flow.u[at(x, y)], from.fx * ray.x() / ray.z() + from.cx - (x + 0.5), 1e-3) << x << "," << y;
      EXPECT_NEAR(flow.v[at(x, y)], from.fy * ray.y() / ray.z() + from.cy - (y + 0.5), 1e-3) << x << "," << y;
    }
}

TEST(OpticalFlow, NearerSurfaceOccludesSkyHasNoFlowAndSkyAtTheTargetIsNotTheSurface) {
  const Camera from = camera(), to = camera(motion(Vec3d(0.5, 0, 0)));
  cv::Mat from_depth = wall(10), to_depth = wall(10);
  from_depth.at<float>(10, 40) = std::numeric_limits<float>::infinity();  // sky in the first view
  from_depth.at<float>(11, 40) = 0.0f;                                    // 0 means no hit too
  to_depth.colRange(0, 20).setTo(4.0f);                                   // a post in front in the second view
  to_depth.at<float>(30, 50) = std::numeric_limits<float>::infinity();    // sky where a wall pixel lands
  const FlowField flow = optical_flow(from, from_depth, to, to_depth);
  EXPECT_EQ(flow.state[at(40, 10)], FlowState::NoDepth);
  EXPECT_EQ(flow.state[at(40, 11)], FlowState::NoDepth);
  EXPECT_EQ(flow.u[at(40, 10)], 0.0f);
  const int lands = int(std::floor(15 + 0.5 - from.fx * 0.05));  // pixel column where x = 15 lands
  EXPECT_LT(lands, 20);
  EXPECT_EQ(flow.state[at(15, 20)], FlowState::Occluded);
  EXPECT_EQ(flow.state[at(60, 20)], FlowState::Valid);
  const int sky_x = int(std::ceil(50 + from.fx * 0.05 - 0.5));  // a wall pixel landing in column 50
  EXPECT_EQ(flow.state[at(sky_x, 30)], FlowState::Occluded);
}

TEST(OpticalFlow, KittiPngAndFloEncodeTheDocumentedValues) {
  FlowField flow;
  flow.width = 3;
  flow.height = 1;
  flow.u = {1.5f, -2.25f, 0.0f};
  flow.v = {-0.5f, 600.0f, 0.0f};
  flow.state = {FlowState::Valid, FlowState::Occluded, FlowState::NoDepth};
  const std::string png = encode_kitti_flow_png(flow);
  const cv::Mat kitti = cv::imdecode(cv::Mat(1, int(png.size()), CV_8U, const_cast<char*>(png.data())), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(kitti.type(), CV_16UC3);
  const cv::Vec3w first = kitti.at<cv::Vec3w>(0, 0);  // OpenCV's order is B, G, R
  EXPECT_EQ(first[2], 1.5 * 64 + 32768);
  EXPECT_EQ(first[1], -0.5 * 64 + 32768);
  EXPECT_EQ(first[0], 1);
  EXPECT_EQ(kitti.at<cv::Vec3w>(0, 1), cv::Vec3w(0, 0, 0));  // not valid: all zero
  const std::string flo = encode_middlebury_flo(flow);
  ASSERT_EQ(flo.size(), 12u + 3 * 8);
  EXPECT_EQ(flo.substr(0, 4), "PIEH");
  float values[6];
  std::memcpy(values, flo.data() + 12, sizeof values);
  EXPECT_EQ(values[0], 1.5f);
  EXPECT_EQ(values[3], 600.0f);   // occluded pixels keep their projection
  EXPECT_EQ(values[4], 1e10f);    // no depth: Middlebury's unknown
  const std::string mask = encode_flow_mask_png(flow);
  const cv::Mat m = cv::imdecode(cv::Mat(1, int(mask.size()), CV_8U, const_cast<char*>(mask.data())), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(m.at<uint8_t>(0, 0), 0);
  EXPECT_EQ(m.at<uint8_t>(0, 1), 1);
  EXPECT_EQ(m.at<uint8_t>(0, 2), 3);
}

}  // namespace
}  // namespace silva::io
