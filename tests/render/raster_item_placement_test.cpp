// Placement of triangle runs of instances that straddle the view: known answers for
// place_points, and a straddling terrain whose runs are placed (dropped / SIMD setup with or
// without the frustum test) rendering exactly like the same triangles in an order that leaves
// every run to the per-triangle tests.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "raster_test_scenes.hpp"
#include "render/item_placement.hpp"
#include "render/renderer.hpp"

namespace silva::render {
namespace {

/// A 90-degree 64x48 view looking down +z from the origin (view space = object space), near 0.1, far 100.
SetupView axis_view() {
  Camera cam = Camera::from_fov(64, 48, 90.0, 0.1, 100.0);
  cam.camera_to_world = Mat4d::Identity();
  return SetupView(ViewProjection::from_camera(cam));
}

/// The identity object -> view transform.
Eigen::Matrix<double, 3, 4> identity() { return Eigen::Matrix<double, 3, 4>::Identity(); }

TEST(ItemPlacement, PointsInFrontInsideTheImageAreInside) {
  const std::vector<Vec3f> pts = {{-1, -1, 5}, {1, 0.5f, 6}, {0, 0, 5.5f}};
  EXPECT_EQ(place_points(pts, identity(), axis_view()), Placement::Inside);
}

TEST(ItemPlacement, PointsBehindTheNearPlaneBeyondTheFarPlaneOrBesideTheImageAreOutside) {
  const SetupView sv = axis_view();
  EXPECT_EQ(place_points(std::vector<Vec3f>{{0, 0, -3}, {1, 1, 0.05f}}, identity(), sv), Placement::Outside);
  EXPECT_EQ(place_points(std::vector<Vec3f>{{0, 0, 101}, {1, 1, 150}}, identity(), sv), Placement::Outside);
  // x > z everywhere: right of the 90-degree image (u = fx * x / z + cx > width).
  EXPECT_EQ(place_points(std::vector<Vec3f>{{7, 0, 5}, {9, 1, 6}}, identity(), sv), Placement::Outside);
}

TEST(ItemPlacement, PointsAcrossAFrustumPlaneInsideTheClipPlanesAreUnclipped) {
  const SetupView sv = axis_view();
  EXPECT_EQ(place_points(std::vector<Vec3f>{{0, 0, 5}, {8, 0, 5}}, identity(), sv), Placement::Unclipped);  // side
  EXPECT_EQ(place_points(std::vector<Vec3f>{{0, 0, 90}, {1, 1, 120}}, identity(), sv), Placement::Unclipped);  // far
  // x = z lies on the right image edge (u = width for fx = cx = 32 at 90 degrees): neither side of it.
  EXPECT_EQ(place_points(std::vector<Vec3f>{{0, 0, 5}, {5, 0, 5}}, identity(), sv), Placement::Unclipped);
  EXPECT_EQ(place_points(std::vector<Vec3f>{{5, 0, 5}, {6, 0, 6}}, identity(), sv), Placement::Unclipped);
}

TEST(ItemPlacement, PointsAcrossAClipPlaneOrNotFiniteStraddle) {
  const SetupView sv = axis_view();
  EXPECT_EQ(place_points(std::vector<Vec3f>{{0, 0, -1}, {0, 0, 5}}, identity(), sv), Placement::Straddles);  // near
  // u = 32 x / z + 32 reaches past the 8192-pixel guard band right of the image.
  EXPECT_EQ(place_points(std::vector<Vec3f>{{0, 0, 1}, {300, 0, 1}}, identity(), sv), Placement::Straddles);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(place_points(std::vector<Vec3f>{{0, 0, 5}, {nan, 0, 5}}, identity(), sv), Placement::Straddles);
  EXPECT_EQ(place_points(std::vector<Vec3f>{}, identity(), sv), Placement::Straddles);
}

TEST(ItemPlacement, TheInstanceTransformIsApplied) {
  const std::vector<Vec3f> pts = {{0, 0, 0}, {0.5f, 0.5f, 0.5f}};
  Eigen::Matrix<double, 3, 4> m = identity();
  m(2, 3) = 5.0;  // moved 5 m in front of the camera
  EXPECT_EQ(place_points(pts, m, axis_view()), Placement::Inside);
  m(2, 3) = -5.0;  // behind it
  EXPECT_EQ(place_points(pts, m, axis_view()), Placement::Outside);
}

/// Renders `grid` and its shuffled twin (triangle t of `shuffled` is triangle order[t] of `grid`)
/// from `cam`; expects the same pixels and counters, and adds the placements of grid's 128-triangle
/// runs (as the geometry pass places them) to `placements`.
void expect_placed_like_shuffled(const Mesh& grid, const Mesh& shuffled, const std::vector<uint32_t>& order,
                                 const Camera& cam, int (&placements)[4]) {
  const SetupView sv(ViewProjection::from_camera(cam));
  const Eigen::Matrix<double, 3, 4> m = sv.view.world_to_view.topRows<3>();
  for (size_t t = 0; t < grid.triangle_count(); t += 128) {
    const auto [lo, hi] = std::minmax_element(grid.indices.begin() + ptrdiff_t(t) * 3,
                                              grid.indices.begin() + ptrdiff_t(std::min(t + 128, grid.triangle_count())) * 3);
    ++placements[int(place_points({grid.positions.data() + *lo, size_t(*hi - *lo + 1)}, m, sv))];
  }
  test::OwnedScene a, b;
  a.add_instance(a.add_mesh(grid));
  b.add_instance(b.add_mesh(shuffled));
  Renderer ra, rb;
  RenderStats sa, sb;
  const VisibilityBuffer& va = ra.render_visibility(a.scene, cam, RenderOptions{}, &sa);
  const VisibilityBuffer& vb = rb.render_visibility(b.scene, cam, RenderOptions{}, &sb);
  EXPECT_EQ(sa.triangles_after_cull, sb.triangles_after_cull);
  EXPECT_EQ(sa.triangles_clipped, sb.triangles_clipped);
  EXPECT_EQ(sa.triangles_rasterised, sb.triangles_rasterised);
  size_t covered = 0, differ = 0;
  for (size_t i = 0; i < va.size(); ++i) {
    covered += va.instance[i] != kNoInstance;
    const bool same = va.instance[i] == vb.instance[i] && va.depth[i] == vb.depth[i] &&
                      (va.instance[i] == kNoInstance || va.triangle[i] == order[vb.triangle[i]]);
    differ += !same;
  }
  EXPECT_GT(covered, 2000u);  // the chunk covers a few thousand pixels at least
  EXPECT_EQ(differ, 0u);
}

TEST(ItemPlacement, PlacedRunsRenderLikeTheSameTrianglesTestedOneByOne) {
  // A 32 m terrain chunk at 0.5 m (64 x 64 quads: one 128-triangle run per row), seen from 10 m up
  // off to one side with the far plane cutting it, then by a camera standing on it: the instance
  // straddles the view, so its runs are placed, and they lie inside, outside (beyond the far
  // plane), across the image's side or far plane (unclipped), and across the near plane
  // (straddling). Shuffled, the same triangles make every run sparse: tested one by one.
  const auto height = [](float x, float y) { return 0.8f * std::sin(0.21f * x) * std::cos(0.17f * y); };
  const Mesh grid = test::make_heightfield(-16.0f, -16.0f, 64, 0.5f, height);
  Mesh shuffled = grid;
  std::vector<uint32_t> order(grid.triangle_count());
  std::iota(order.begin(), order.end(), 0u);
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  for (size_t t = 0; t < order.size(); ++t)
    for (int k = 0; k < 3; ++k) shuffled.indices[t * 3 + size_t(k)] = grid.indices[size_t(order[t]) * 3 + size_t(k)];
  int placements[4] = {};
  Camera above = Camera::from_fov(320, 200, 90.0, 0.05, 45.0);
  above.camera_to_world = pose_from_angles(Vec3d(-20.0, -40.0, 10.0), 90.0, -15.0, 0.0);
  expect_placed_like_shuffled(grid, shuffled, order, above, placements);
  Camera standing = Camera::from_fov(320, 200, 90.0, 0.05, 150.0);
  standing.camera_to_world = pose_from_angles(Vec3d(0.0, -10.0, height(0.0f, -10.0f) + 0.02), 70.0, -30.0, 0.0);
  expect_placed_like_shuffled(grid, shuffled, order, standing, placements);
  EXPECT_GT(placements[int(Placement::Outside)], 0);
  EXPECT_GT(placements[int(Placement::Inside)], 0);
  EXPECT_GT(placements[int(Placement::Unclipped)], 0);
  EXPECT_GT(placements[int(Placement::Straddles)], 0);
}

}  // namespace
}  // namespace silva::render
