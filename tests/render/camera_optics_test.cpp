// The camera model's optics on linear frames: vignetting, chromatic aberration, depth of field
// and motion blur against known answers and properties.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/camera_model.hpp"
#include "render/camera_encode.hpp"
#include "render/chromatic_aberration.hpp"
#include "render/depth_of_field.hpp"
#include "render/motion_blur.hpp"

namespace silva::render {
namespace {

/// A frame of vertical bars `period` pixels wide alternating between 0.1 and 0.9 (all channels).
LinearFrame bars(const Camera& cam, int period) {
  LinearFrame f;
  f.resize(cam.width, cam.height);
  for (int v = 0; v < cam.height; ++v)
    for (int u = 0; u < cam.width; ++u)
      f.rgb[size_t(v) * size_t(cam.width) + size_t(u)] = Vec3f::Constant((u / period) % 2 ? 0.9f : 0.1f);
  return f;
}

/// Std-dev of the green channel over the pixels of rows [v0, v1) and columns [u0, u1).
double spread(const LinearFrame& f, int u0, int u1, int v0, int v1) {
  double n = 0, m1 = 0, m2 = 0;
  for (int v = v0; v < v1; ++v)
    for (int u = u0; u < u1; ++u) {
      const double g = f.at(u, v).y();
      n += 1;
      m1 += g;
      m2 += g * g;
    }
  m1 /= n;
  return std::sqrt(std::max(m2 / n - m1 * m1, 0.0));
}

TEST(CameraOptics, VignettingFollowsTheCosFourthLaw) {
  EXPECT_EQ(vignetting_factor(0, 0, 1), 1.0f);
  EXPECT_NEAR(vignetting_factor(1, 0, 1), 0.25f, 1e-6f);  // 45 degrees off axis: cos^4 = 1/4
  EXPECT_NEAR(vignetting_factor(1, 1, 1), 1.0f / 9.0f, 1e-6f);  // tan^2 = 2: cos^2 = 1/3
  EXPECT_NEAR(vignetting_factor(1, 0, 0.2f), 0.8f + 0.2f * 0.25f, 1e-6f);
  EXPECT_EQ(vignetting_factor(1, 1, 0), 1.0f);
  // Encoded: a flat card gets darker towards the corners, symmetrically.
  const Camera cam = Camera::from_fov(64, 48, 90, 0.05, 150);
  CameraModel model;
  model.vignetting = 1;
  RowEncoder encoder(cam, model, 1.0f, 1, 2);
  const std::vector<float> row(64 * 3, 0.5f);
  std::vector<uint8_t> top(64 * 3), middle(64 * 3);
  encoder.encode(0, row.data(), top.data());
  encoder.encode(24, row.data(), middle.data());
  EXPECT_GT(middle[3 * 32], middle[3 * 8]);
  EXPECT_GT(middle[3 * 8], top[3 * 8]);
  EXPECT_EQ(middle[3 * 10], middle[3 * 53]);
}

TEST(CameraOptics, ChromaticAberrationShiftsRedInwardAndBlueOutward) {
  const Camera cam = Camera::from_fov(101, 61, 90, 0.05, 150);  // principal point (50.5, 30.5)
  LinearFrame in;
  in.resize(cam.width, cam.height);
  for (int v = 0; v < cam.height; ++v)
    for (int u = 0; u < cam.width; ++u) in.rgb[size_t(v) * 101 + size_t(u)] = Vec3f::Constant(float(u));  // a ramp in x
  LinearFrame out;
  apply_chromatic_aberration(in, cam, 0.02f, out);
  for (int u : {5, 30, 70, 95}) {
    const Vec3f p = out.at(u, 30);
    const float dx = float(u) + 0.5f - 50.5f;
    EXPECT_NEAR(p.x(), 50.0f + dx * 0.98f, 1e-3f) << u;  // red from radius x 0.98
    EXPECT_EQ(p.y(), float(u));                           // green untouched
    EXPECT_NEAR(p.z(), 50.0f + dx * 1.02f, 1e-3f) << u;  // blue from radius x 1.02
  }
  EXPECT_EQ(out.at(50, 30), in.at(50, 30));  // the centre pixel does not move
}

TEST(CameraOptics, CircleOfConfusionKnownAnswers) {
  Camera cam = Camera::from_fov(1920, 1080, 90, 0.05, 150);  // fx = 960
  const DepthOfField dof{2.0, 2.0, 50.0};
  const double scale = 960.0 * 0.05 / (2.0 * 1.95);  // fx f / (N (s - f)) = 12.3077 px
  EXPECT_NEAR(coc_diameter_px(dof, cam, 2.0f), 0.0, 1e-6);
  EXPECT_NEAR(coc_diameter_px(dof, cam, 4.0f), scale * 0.5, 1e-4);
  EXPECT_NEAR(coc_diameter_px(dof, cam, 1.0f), scale * 1.0, 1e-4);
  EXPECT_NEAR(coc_diameter_px(dof, cam, 0.0f), scale, 1e-4);  // sky: infinitely far
}

TEST(CameraOptics, DepthOfFieldKeepsTheFocusPlaneSharpAndBlursTheRest) {
  const Camera cam = Camera::from_fov(160, 96, 90, 0.05, 150);  // fx = 80
  const DepthOfField dof{0.5, 2.0, 100.0};                       // scale 80 * 0.1 / (0.5 * 1.9) = 8.4 px
  const LinearFrame in = bars(cam, 3);
  // Left half in focus at 2 m, right half far (or sky) behind it.
  std::vector<float> depth(in.rgb.size());
  for (int v = 0; v < cam.height; ++v)
    for (int u = 0; u < cam.width; ++u) depth[size_t(v) * 160 + size_t(u)] = u < 80 ? 2.0f : (v < 48 ? 50.0f : 0.0f);
  LinearFrame out;
  apply_depth_of_field(in, depth, cam, dof, out);
  for (int v = 0; v < cam.height; ++v)
    for (int u = 0; u < 80; ++u)  // in focus, even beside the blurred background: unchanged
      ASSERT_EQ(out.at(u, v), in.at(u, v)) << u << "," << v;
  EXPECT_GT(spread(in, 100, 150, 10, 40), 0.39);
  EXPECT_LT(spread(out, 100, 150, 10, 40), 0.5 * spread(in, 100, 150, 10, 40));  // far: blurred
  EXPECT_LT(spread(out, 100, 150, 60, 90), 0.5 * spread(in, 100, 150, 60, 90));  // sky: blurred
  double mean_in = 0, mean_out = 0;
  for (int v = 10; v < 40; ++v)
    for (int u = 100; u < 150; ++u) mean_in += in.at(u, v).y(), mean_out += out.at(u, v).y();
  EXPECT_NEAR(mean_out / mean_in, 1.0, 0.05);  // blur moves light, it does not make it
  // All in focus: the frame comes back unchanged.
  LinearFrame sharp;
  apply_depth_of_field(in, std::vector<float>(in.rgb.size(), 2.0f), cam, dof, sharp);
  EXPECT_EQ(sharp.rgb, in.rgb);
}

TEST(CameraOptics, MotionEndpointsOfASidewaysMoveFollowDepth) {
  Camera cam = Camera::from_fov(200, 100, 90, 0.05, 150);  // fx = 100
  cam.camera_to_world = pose_from_angles(Vec3d(0, 0, 1.5), 0, 0, 0);  // looks along +X; camera x is world -Y
  const ExposureMotion motion{0.01, pose_from_angles(Vec3d(0, 0.1, 1.5), 0, 0, 0),
                              pose_from_angles(Vec3d(0, -0.1, 1.5), 0, 0, 0)};  // 0.2 m to the right
  Vec2f open, close;
  ASSERT_TRUE(motion_endpoints(cam, motion, 120, 50, 4.0f, open, close));
  // The camera moves +0.2 m along its x: a point at 4 m moves fx * 0.2 / 4 = 5 px to the left.
  EXPECT_NEAR(close.x() - open.x(), -5.0f, 1e-4f);
  EXPECT_NEAR(close.y() - open.y(), 0.0f, 1e-4f);
  EXPECT_NEAR(0.5f * (open.x() + close.x()), 120.5f, 1e-4f);  // the frame's pose is mid-exposure
  ASSERT_TRUE(motion_endpoints(cam, motion, 120, 50, 0.0f, open, close));
  EXPECT_NEAR((close - open).norm(), 0.0f, 1e-5f);  // sky does not move under translation
}

TEST(CameraOptics, MotionBlurSmearsAlongTheMotionOnly) {
  Camera cam = Camera::from_fov(200, 100, 90, 0.05, 150);
  cam.camera_to_world = pose_from_angles(Vec3d(0, 0, 1.5), 0, 0, 0);
  const ExposureMotion motion{0.01, pose_from_angles(Vec3d(0, 0.16, 1.5), 0, 0, 0),
                              pose_from_angles(Vec3d(0, -0.16, 1.5), 0, 0, 0)};
  const LinearFrame in = bars(cam, 4);
  LinearFrame transposed = in;  // horizontal bars: along the motion, so they stay sharp
  for (int v = 0; v < cam.height; ++v)
    for (int u = 0; u < cam.width; ++u)
      transposed.rgb[size_t(v) * 200 + size_t(u)] = Vec3f::Constant((v / 4) % 2 ? 0.9f : 0.1f);
  std::vector<float> depth(in.rgb.size(), 2.0f);  // 16 px of motion at 2 m: two periods of the bars
  LinearFrame out;
  apply_motion_blur(in, depth, cam, motion, out);
  EXPECT_LT(spread(out, 20, 180, 10, 90), 0.2 * spread(in, 20, 180, 10, 90));
  apply_motion_blur(transposed, depth, cam, motion, out);
  for (int v = 0; v < cam.height; ++v)
    for (int u = 20; u < 180; ++u) ASSERT_NEAR(out.at(u, v).y(), transposed.at(u, v).y(), 1e-5f) << u << "," << v;
  apply_motion_blur(in, std::vector<float>(in.rgb.size(), 0.0f), cam, motion, out);  // all sky
  EXPECT_EQ(out.rgb, in.rgb);
}

}  // namespace
}  // namespace silva::render
