// Depth, clipping and attribute known-answer tests against analytic ray-plane hits.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "raster_test_scenes.hpp"
#include "render/raster_conventions.hpp"
#include "render/renderer.hpp"

namespace silva::render {
namespace {

using test::OwnedScene;

/// Ray-triangle hit in double (Moller-Trumbore): returns t along dir (camera z = 1: metric z),
/// or a negative value for a miss; `margin` gets the smallest barycentric.
double ray_triangle(const Vec3d& o, const Vec3d& d, const Vec3d& a, const Vec3d& b, const Vec3d& c, double& margin) {
  const Vec3d e1 = b - a, e2 = c - a, p = d.cross(e2);
  const double det = e1.dot(p);
  if (det == 0.0) return -1.0;
  const Vec3d s = o - a, q = s.cross(e1);
  const double u = s.dot(p) / det, v = d.dot(q) / det;
  margin = std::min({u, v, 1.0 - u - v});
  return margin >= 0.0 ? e2.dot(q) / det : -1.0;
}

/// Where pixel (u, v)'s centre ray from `cam` hits triangle abc: t (camera z; negative for a miss)
/// and the smallest barycentric (near 0 on an edge).
struct PixelHit {
  double t = -1.0;       ///< Metric z of the hit, or negative.
  double margin = 0.0;   ///< Smallest barycentric of the hit point.
};

/// PixelHit of triangle (a, b, c) (world positions) for pixel (u, v) of `cam`.
PixelHit pixel_hit(const Camera& cam, int u, int v, const Vec3f& a, const Vec3f& b, const Vec3f& c) {
  PixelHit h;
  h.t = ray_triangle(cam.position(), cam.ray_direction(u, v), a.cast<double>(), b.cast<double>(), c.cast<double>(),
                     h.margin);
  return h;
}

TEST(RasterDepth, VisibilityBufferHoldsEachPixelsWinnerAndClearsEmptyPixels) {
  // 37 x 23 pixels: rows end in a partial SIMD vector on every target. A quad 5 m ahead covers
  // the middle-left of the view; the rest sees nothing.
  Camera cam = Camera::from_fov(37, 23, 60.0, 0.05, 150.0);
  cam.camera_to_world = pose_from_angles(Vec3d(2.0, 1.0, 1.5), 30.0, 5.0, 0.0);
  const auto world = [&](double x, double y) { return Vec3f((cam.camera_to_world * Vec4d(x, y, 5.0, 1.0)).head<3>().cast<float>()); };
  const Vec3f q[4] = {world(-1.5, -1.0), world(0.5, -1.0), world(0.5, 1.0), world(-1.5, 1.0)};
  OwnedScene s;
  s.add_instance(s.add_mesh(test::make_quad(q[0], q[1], q[2], q[3], Role::Obstacle, true)));
  Renderer renderer;
  const VisibilityBuffer& vis = renderer.render_visibility(s.scene, cam, RenderOptions{});
  int hits = 0, empty = 0;
  for (int v = 0; v < cam.height; ++v)
    for (int u = 0; u < cam.width; ++u) {
      const size_t i = size_t(v) * size_t(cam.width) + size_t(u);
      const PixelHit h0 = pixel_hit(cam, u, v, q[0], q[1], q[2]), h1 = pixel_hit(cam, u, v, q[0], q[2], q[3]);
      const double t0 = h0.t, t1 = h1.t;
      if (std::abs(h0.margin) < 1e-3 || std::abs(h1.margin) < 1e-3) continue;  // on an edge: either answer is right
      if (t0 < 0.0 && t1 < 0.0) {
        EXPECT_EQ(vis.depth[i], 0.0f) << u << "," << v;
        EXPECT_EQ(vis.instance[i], kNoInstance) << u << "," << v;
        EXPECT_EQ(vis.triangle[i], 0u) << u << "," << v;
        ++empty;
        continue;
      }
      EXPECT_EQ(vis.instance[i], 0u) << u << "," << v;
      EXPECT_EQ(vis.triangle[i], t0 >= 0.0 ? 0u : 1u) << u << "," << v;
      EXPECT_NEAR(double(vis.depth[i]) * std::max(t0, t1), 1.0, 1e-5) << u << "," << v;  // d = 1/z
      ++hits;
    }
  EXPECT_GT(hits, 80);
  EXPECT_GT(empty, 300);
}

TEST(RasterDepth, SteepTriangleDrawnAfterAWallWinsExactlyWhereItIsNearer) {
  // One mesh, so every tile sees the wall (triangle 0) first and then a triangle slanting from
  // 6 m to 14 m through it (triangle 1): the early depth tests of triangle 1 run against blocks
  // the wall already filled, where its depth range straddles the wall's. A block test that used
  // the triangle's far corner instead of its near one would drop its nearer pixels there.
  Camera cam = Camera::from_fov(128, 96, 60.0, 0.05, 150.0);
  cam.camera_to_world = pose_from_angles(Vec3d(0.0, 0.0, 1.5), 0.0, 0.0, 0.0);
  Mesh m;
  m.positions = {{10, -50, -50}, {10, 50, -50}, {10, 0, 60}, {6, -3, -1}, {6, -3, 4}, {14, 5, 1.5f}};
  m.indices = {0, 1, 2, 3, 4, 5};
  m.compute_normals();
  test::one_part(m, Role::Obstacle, Material::Ground, true);
  OwnedScene s;
  s.add_instance(s.add_mesh(m));
  Renderer renderer;
  const VisibilityBuffer& vis = renderer.render_visibility(s.scene, cam, RenderOptions{});
  const std::vector<Vec3f>& p = m.positions;
  int steep = 0, wall = 0;
  for (int v = 0; v < cam.height; ++v)
    for (int u = 0; u < cam.width; ++u) {
      const size_t i = size_t(v) * size_t(cam.width) + size_t(u);
      const double tw = pixel_hit(cam, u, v, p[0], p[1], p[2]).t;
      const PixelHit hs = pixel_hit(cam, u, v, p[3], p[4], p[5]);
      const double ts = hs.t;
      if (std::abs(hs.margin) < 1e-3 || (ts >= 0.0 && std::abs(ts - tw) < 1e-4 * tw)) continue;  // edge or near-tie
      ASSERT_GE(tw, 0.0) << "the wall fills the view";
      const bool steep_wins = ts >= 0.0 && ts < tw;
      EXPECT_EQ(vis.triangle[i], steep_wins ? 1u : 0u) << u << "," << v;
      (steep_wins ? steep : wall) += 1;
    }
  EXPECT_GT(steep, 300);
  EXPECT_GT(wall, 3000);
}

TEST(RasterDepth, DepthAtPixelCentresEqualsAnalyticRayPlaneZ) {
  Camera cam = Camera::from_fov(160, 120, 75.0, 0.05, 150.0);
  cam.camera_to_world = pose_from_angles(Vec3d(1.0, -2.0, 1.5), 20.0, -10.0, 5.0);
  const Vec3f quads[3][4] = {
      {{4, -8, -1}, {30, -12, -3}, {34, 14, 6}, {8, 18, 8}},      // slanted parallelogram
      {{-5, -40, 0}, {120, -40, 0}, {120, 40, 0}, {-5, 40, 0}},  // ground plane to the horizon
      {{3, 1, 0}, {3, -1, 0.5f}, {3.5f, -1, 2.5f}, {3.5f, 1, 2}}};  // near, steep
  Renderer renderer;
  for (const auto& q : quads) {
    OwnedScene s;
    s.add_instance(s.add_mesh(test::make_quad(q[0], q[1], q[2], q[3], Role::Ground, true)));
    GBuffer g;
    renderer.render_gbuffer(s.scene, cam, RenderOptions{}, g);
    const Vec3d a = q[0].cast<double>(), b = q[1].cast<double>(), c = q[2].cast<double>();
    const Vec3d n = (b - a).cross(c - a);
    int hits = 0;
    for (int v = 0; v < cam.height; ++v)
      for (int u = 0; u < cam.width; ++u) {
        const size_t i = size_t(v) * size_t(cam.width) + size_t(u);
        if (g.depth[i] == 0.0f) continue;
        const Vec3d dir = cam.ray_direction(u, v);
        const double z = n.dot(a - cam.position()) / n.dot(dir);  // ray-plane t, camera z = 1
        ASSERT_LT(std::abs(double(g.depth[i]) - z) / z, 1e-5) << u << "," << v;
        ++hits;
      }
    EXPECT_GT(hits, 500);
  }
}

TEST(RasterDepth, TriangleCrossingTheCameraPlaneIsClippedAtNear) {
  // Plane x + z = 0.06 (camera space = world here): z < near = 0.05 for u > cx + 0.2 fx.
  Camera cam = Camera::from_fov(64, 48, 90.0, 0.05, 150.0);
  cam.camera_to_world = Mat4d::Identity();
  const Vec3f p0(-1, -1, 1.06f), p1(-1, 1, 1.06f), p2(0.5f, 0, -0.44f);
  Mesh m;
  m.positions = {p0, p1, p2};
  m.indices = {0, 1, 2};
  m.uvs.assign(3, Vec2f::Zero());
  m.compute_normals();
  test::one_part(m, Role::Obstacle, Material::Rock, true);
  OwnedScene s;
  s.add_instance(s.add_mesh(std::move(m)), Affine3f::Identity(), 42);
  Renderer renderer;
  GBuffer g;
  RenderStats stats;
  renderer.render_gbuffer(s.scene, cam, RenderOptions{}, g, &stats);
  EXPECT_EQ(stats.triangles_clipped, 1u);
  int hits = 0, clipped_away = 0;
  for (int v = 0; v < cam.height; ++v)
    for (int u = 0; u < cam.width; ++u) {
      const size_t i = size_t(v) * size_t(cam.width) + size_t(u);
      double margin = 0;
      const double z = ray_triangle(Vec3d::Zero(), cam.ray_direction(u, v), p0.cast<double>(), p1.cast<double>(),
                                    p2.cast<double>(), margin);
      if (std::abs(margin) < 1e-3) continue;  // sample on an edge: either answer is fine
      const bool want = z >= cam.near;
      clipped_away += z > 0.0 && z < cam.near;
      ASSERT_EQ(want, g.depth[i] > 0.0f) << u << "," << v << " z " << z;
      if (!want) continue;
      ++hits;
      EXPECT_LT(std::abs(double(g.depth[i]) - z) / z, 1e-5);
      EXPECT_EQ(g.role[i], Role::Obstacle);
      EXPECT_EQ(g.instance_id[i], 42u);
    }
  EXPECT_GT(hits, 100);
  EXPECT_GT(clipped_away, 50);  // the near plane really cut the triangle inside the image
}

TEST(RasterDepth, UvIsPerspectiveCorrectOnASlantedQuad) {
  Camera cam = Camera::from_fov(128, 96, 90.0, 0.05, 150.0);
  cam.camera_to_world = pose_from_angles(Vec3d(0, 0, 1.0), 0.0, -15.0, 0.0);
  // A 4 m x 30 m rectangle on the ground receding from 0.5 m to 30.5 m: strong foreshortening.
  const Vec3f p0(0.5f, 2, 0), p1(0.5f, -2, 0), p2(30.5f, -2, 0), p3(30.5f, 2, 0);
  OwnedScene s;
  s.add_instance(s.add_mesh(test::make_quad(p0, p1, p2, p3, Role::Trail)));
  Renderer renderer;
  GBuffer g;
  renderer.render_gbuffer(s.scene, cam, RenderOptions{}, g);
  const Vec3d o = p0.cast<double>(), eu = (p1 - p0).cast<double>(), ev = (p3 - p0).cast<double>();
  int hits = 0;
  double worst = 0;
  for (int v = 0; v < cam.height; ++v)
    for (int u = 0; u < cam.width; ++u) {
      const size_t i = size_t(v) * size_t(cam.width) + size_t(u);
      if (g.depth[i] == 0.0f) continue;
      const Vec3d dir = cam.ray_direction(u, v);
      const Vec3d hit = cam.position() + (-cam.position().z() / dir.z()) * dir;  // ground z = 0
      const double su = (hit - o).dot(eu) / eu.squaredNorm(), sv = (hit - o).dot(ev) / ev.squaredNorm();
      worst = std::max({worst, std::abs(g.uv[i].x() - su), std::abs(g.uv[i].y() - sv)});
      EXPECT_EQ(g.role[i], Role::Trail);
      EXPECT_NEAR(g.normal[i].z(), 1.0f, 1e-5f);
      EXPECT_NEAR(g.position[i].z(), 0.0f, 1e-4f);
      ++hits;
    }
  EXPECT_GT(hits, 2000);
  EXPECT_LT(worst, 1e-4);
}

TEST(RasterDepth, BackFaceNormalIsTurnedToFaceTheCamera) {
  Camera cam = Camera::from_fov(32, 24, 90.0, 0.05, 150.0);
  cam.camera_to_world = Mat4d::Identity();
  // Counter-clockwise from +z: the camera (looking along +z) sees its back side.
  OwnedScene s;
  s.add_instance(s.add_mesh(test::make_quad({-5, -5, 2}, {5, -5, 2}, {5, 5, 2}, {-5, 5, 2}, Role::Shrub, true)));
  Renderer renderer;
  GBuffer g;
  renderer.render_gbuffer(s.scene, cam, RenderOptions{}, g);
  for (size_t i = 0; i < g.size(); ++i) {
    ASSERT_FLOAT_EQ(g.depth[i], 2.0f);
    ASSERT_NEAR(g.normal[i].z(), -1.0f, 1e-6f);
  }
}

}  // namespace
}  // namespace silva::render
