// SIMD vertex projection of the triangle setup: the scalar path's bits on every Highway target,
// known answers for the sub-pixel rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "highway_targets.hpp"
#include "render/vertex_lanes.hpp"

namespace silva::render {
namespace {

/// The scalar setup's vertex: view position, then projection and snapping.
SetupVertex scalar_vertex(const Eigen::Matrix<double, 3, 4>& m, const ViewProjection& view, const Vec3f& p) {
  SetupVertex v;
  v.p = to_view(m, p);
  project_vertex(view, v);
  return v;
}

/// True when both vertices hold the same bits in every field.
bool same_bits(const SetupVertex& a, const SetupVertex& b) {
  return a.p.x() == b.p.x() && a.p.y() == b.p.y() && a.p.z() == b.p.z() && a.x == b.x && a.y == b.y &&
         a.depth == b.depth && a.projected == b.projected;
}

TEST(VertexLanes, MatchTheScalarSetupOnEveryHighwayTarget) {
  const ViewProjection view = ViewProjection::from_camera(Camera::from_fov(1920, 1080, 70.0, 0.05, 150.0));
  std::mt19937 gen(11);
  std::uniform_real_distribution<float> coord(-3.0f, 3.0f);
  // An instance rotated about a tilted axis, scaled and placed 10-20 m in front of the camera.
  Eigen::Affine3d object_to_view = Eigen::Translation3d(0.7, -0.4, 15.0) *
                                   Eigen::AngleAxisd(0.83, Vec3d(0.3, 1.0, -0.2).normalized()) * Eigen::Scaling(1.7);
  const Eigen::Matrix<double, 3, 4> m = object_to_view.matrix().topRows<3>();
  std::vector<Vec3f> positions(37);  // full vectors and a tail on every target
  for (Vec3f& p : positions) p = Vec3f(coord(gen), coord(gen), coord(gen));
  std::vector<SetupVertex> expected;
  for (const Vec3f& p : positions) expected.push_back(scalar_vertex(m, view, p));
  const std::vector<int64_t> targets = test::highway_targets();
  ASSERT_GE(targets.size(), 2u);
  for (int64_t target : targets) {
    const test::PinnedTarget pinned(target);
    ASSERT_EQ(vertex_simd_target(), target);
    SCOPED_TRACE(hwy::TargetName(target));
    for (size_t count : {size_t(1), size_t(5), positions.size()}) {
      std::vector<SetupVertex> out(count);
      project_vertices(m, view, positions.data(), count, out.data());
      for (size_t i = 0; i < count; ++i) EXPECT_TRUE(same_bits(out[i], expected[i])) << "vertex " << i << " of " << count;
    }
  }
}

TEST(VertexLanes, SnapRoundsHalvesAwayFromZero) {
  // Identity view with fx = fy = 1 and no centre offset: u = x / z, snapped to u * 256.
  ViewProjection view;
  view.fx = view.fy = 1.0;
  view.cx = view.cy = 0.0;
  Eigen::Matrix<double, 3, 4> m = Eigen::Matrix<double, 3, 4>::Zero();
  m.leftCols<3>().setIdentity();
  const std::vector<Vec3f> positions = {Vec3f(1.0f / 512, -1.0f / 512, 1), Vec3f(3.0f / 512, -3.0f / 512, 1),
                                        Vec3f(1.0f / 1024, -1.0f / 1024, 1), Vec3f(5.0f, -2.0f, 4)};
  const int64_t want_x[] = {1, 2, 0, 320}, want_y[] = {-1, -2, 0, -128};  // 0.5, 1.5, 0.25, 5/4*256
  for (int64_t target : test::highway_targets()) {
    const test::PinnedTarget pinned(target);
    SCOPED_TRACE(hwy::TargetName(target));
    std::vector<SetupVertex> out(positions.size());
    project_vertices(m, view, positions.data(), positions.size(), out.data());
    for (size_t i = 0; i < positions.size(); ++i) {
      EXPECT_EQ(out[i].x, want_x[i]) << i;
      EXPECT_EQ(out[i].y, want_y[i]) << i;
      EXPECT_EQ(out[i].depth, 1.0 / double(positions[i].z())) << i;
      EXPECT_TRUE(out[i].projected);
    }
  }
}

}  // namespace
}  // namespace silva::render
