// Coverage known-answer tests: exact sample coverage with the top-left rule, watertight meshes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "raster_test_scenes.hpp"
#include "render/raster_conventions.hpp"
#include "render/renderer.hpp"

namespace silva::render {
namespace {

using test::OwnedScene;

/// A 90-degree camera at the world origin whose axes are the world's (x right, y down, z forward).
Camera screen_camera(int w, int h, double far = 150.0) {
  Camera c = Camera::from_fov(w, h, 90.0, 0.05, far);
  c.camera_to_world = Mat4d::Identity();
  return c;
}

/// The point at view depth z that projects to continuous pixel position (u, v).
Vec3f unproject(const Camera& c, double u, double v, double z) {
  return Vec3f(float((u - c.cx) / c.fx * z), float((v - c.cy) / c.fy * z), float(z));
}

/// A point on the sub-pixel grid, in 1/256 pixel units.
struct Fixed {
  int64_t x, y;
};

/// Side of p against edge a->b (twice the signed area).
int64_t cross(const Fixed& a, const Fixed& b, const Fixed& p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

/// Direct3D ownership of a sample exactly on edge a-b of triangle (a, b, c): top or left edge.
bool owns_edge(const Fixed& a, const Fixed& b, const Fixed& c) {
  if (a.y == b.y) return c.y > a.y;  // horizontal: a top edge has the triangle below it (y down)
  const int64_t dy = b.y - a.y;
  const int64_t right = (c.x - a.x) * dy - (c.y - a.y) * (b.x - a.x);  // c right of the edge line
  return dy > 0 ? right > 0 : right < 0;
}

/// Expected coverage of the sample at p (independent of orientation).
bool expected_inside(const Fixed (&t)[3], const Fixed& p) {
  for (int i = 0; i < 3; ++i) {
    const Fixed &a = t[i], &b = t[(i + 1) % 3], &c = t[(i + 2) % 3];
    const int64_t sp = cross(a, b, p), sc = cross(a, b, c);
    const bool same_side = (sp > 0 && sc > 0) || (sp < 0 && sc < 0);
    if (!same_side && !(sp == 0 && owns_edge(a, b, c))) return false;
  }
  return true;
}

TEST(RasterCoverage, TriangleCoversExactlyTheSampleCentresInsideIt) {
  const int W = 64, H = 48;
  const Camera cam = screen_camera(W, H);
  std::mt19937 gen(12345);
  Renderer renderer;
  int checked = 0, covered_total = 0;
  for (int trial = 0; trial < 300; ++trial) {
    // Coarse grids put vertices on pixel centres and edges through sample rows/columns.
    const int64_t grain = trial % 3 == 0 ? 128 : (trial % 3 == 1 ? 64 : 1);
    std::uniform_int_distribution<int64_t> gx(-10 * 256 / grain, (W + 10) * 256 / grain);
    std::uniform_int_distribution<int64_t> gy(-10 * 256 / grain, (H + 10) * 256 / grain);
    Fixed t[3];
    for (auto& p : t) p = Fixed{gx(gen) * grain, gy(gen) * grain};
    if (cross(t[0], t[1], t[2]) == 0) continue;
    Mesh m;
    for (const auto& p : t) m.positions.push_back(unproject(cam, double(p.x) / 256.0, double(p.y) / 256.0, 1.0 + 0.1 * (trial % 5)));
    m.indices = {0, 1, 2};
    m.uvs.assign(3, Vec2f::Zero());
    m.compute_normals();
    test::one_part(m, Role::Ground, Material::Ground, /*double_sided=*/true);
    OwnedScene s;
    s.add_instance(s.add_mesh(std::move(m)));
    RenderOptions opt;
    opt.tile_size = trial % 2 == 0 ? 16 : 64;
    const VisibilityBuffer& vis = renderer.render_visibility(s.scene, cam, opt);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const bool want = expected_inside(t, Fixed{x * 256 + 128, y * 256 + 128});
        const bool got = vis.instance[size_t(y) * W + size_t(x)] != kNoInstance;
        ASSERT_EQ(want, got) << "trial " << trial << " pixel " << x << "," << y;
        covered_total += got;
      }
    ++checked;
  }
  EXPECT_GT(checked, 250);
  EXPECT_GT(covered_total, 10000);  // the triangles are not all off-screen
}

/// A jittered grid of front-facing triangles over [-3, W+3] x [-3, H+3] pixels on the view-space
/// plane n . X = k (optionally with its winding flipped).
Mesh screen_grid(const Camera& cam, int nx, int ny, const Vec3d& n, double k, bool flip, std::mt19937& gen) {
  const int W = cam.width, H = cam.height;
  std::uniform_real_distribution<double> jitter(-0.35, 0.35);
  Mesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      double u = -3.0 + (W + 6.0) * i / nx, v = -3.0 + (H + 6.0) * j / ny;
      if (i > 0 && i < nx) u += jitter(gen) * (W + 6.0) / nx;
      if (j > 0 && j < ny) v += jitter(gen) * (H + 6.0) / ny;
      u = std::round(u * 256.0) / 256.0;  // exact sub-pixel positions: shared vertices stay shared
      v = std::round(v * 256.0) / 256.0;
      const Vec3d r((u - cam.cx) / cam.fx, (v - cam.cy) / cam.fy, 1.0);
      const double t = k / n.dot(r);
      m.positions.push_back(unproject(cam, u, v, t));
    }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const uint32_t a = uint32_t(j * (nx + 1) + i), b = a + 1, c = a + uint32_t(nx + 1), d = c + 1;
      // Front faces have negative area on the y-down screen: a, d, b is counter-clockwise on screen.
      if ((i + j + int(gen() % 2)) % 2 == 0) {
        m.indices.insert(m.indices.end(), {a, d, b, a, c, d});
      } else {
        m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
      }
    }
  if (flip)
    for (size_t t = 0; t < m.indices.size(); t += 3) std::swap(m.indices[t + 1], m.indices[t + 2]);
  m.uvs.assign(m.positions.size(), Vec2f::Zero());
  m.compute_normals();
  test::one_part(m, Role::Ground);
  return m;
}

TEST(RasterCoverage, TilingMeshCoversEveryPixelExactlyOnce) {
  const Camera cam = screen_camera(93, 71);  // partial tiles: rows of tiles end mid-vector
  std::mt19937 gen(7);
  Renderer renderer;
  const Vec3d planes[3] = {Vec3d(0, 0, 1), Vec3d(0.3, -0.2, 1), Vec3d(-0.5, 0.4, 1)};
  for (int p = 0; p < 3; ++p) {
    OwnedScene s;
    s.add_instance(s.add_mesh(screen_grid(cam, 23, 17, planes[p], 2.0, false, gen)));
    for (int tile : {8, 64}) {
      RenderOptions opt;
      opt.tile_size = tile;
      RenderStats stats;
      const VisibilityBuffer& vis = renderer.render_visibility(s.scene, cam, opt, &stats);
      const uint64_t pixels = uint64_t(cam.width) * uint64_t(cam.height);
      EXPECT_EQ(stats.pixels_covered, pixels) << "cracks, plane " << p;
      EXPECT_EQ(stats.fragments_covered, pixels) << "double coverage, plane " << p;
      for (uint32_t inst : vis.instance) ASSERT_EQ(inst, 0u);
    }
  }
}

TEST(RasterCoverage, BackFacesAreCulledUnlessDoubleSided) {
  const Camera cam = screen_camera(64, 48);
  std::mt19937 gen(3);
  Renderer renderer;
  OwnedScene s;
  s.add_instance(s.add_mesh(screen_grid(cam, 8, 6, Vec3d(0, 0, 1), 2.0, /*flip=*/true, gen)));
  RenderStats stats;
  renderer.render_visibility(s.scene, cam, RenderOptions{}, &stats);
  EXPECT_EQ(stats.pixels_covered, 0u);
  RenderOptions no_cull;
  no_cull.backface_cull = false;
  renderer.render_visibility(s.scene, cam, no_cull, &stats);
  EXPECT_EQ(stats.pixels_covered, 64u * 48u);
  EXPECT_EQ(stats.fragments_covered, 64u * 48u);
  s.meshes[0]->parts[0].double_sided = true;
  renderer.render_visibility(s.scene, cam, RenderOptions{}, &stats);
  EXPECT_EQ(stats.fragments_covered, 64u * 48u);
}

TEST(RasterCoverage, FloorCrossingNearPlaneAndGuardBandIsWatertight) {
  // A jittered floor grid y = 1 (view space) from behind the camera (z = -4) to z = 120, far
  // outside the guard band sideways: every pixel whose ray meets the floor within far is hit,
  // exactly once. With far = 60 some covered samples lie beyond far and must stay empty.
  const int W = 64, H = 48;
  std::mt19937 gen(11);
  std::uniform_real_distribution<float> jitter(-1.2f, 1.2f);
  Mesh m;
  const int nx = 40, nz = 31;
  for (int j = 0; j <= nz; ++j)
    for (int i = 0; i <= nx; ++i) {
      float x = -200.0f + 10.0f * float(i), z = -4.0f + 4.0f * float(j);
      if (i > 0 && i < nx) x += jitter(gen);
      if (j > 0 && j < nz) z += jitter(gen);
      m.positions.emplace_back(x, 1.0f, z);
    }
  for (int j = 0; j < nz; ++j)
    for (int i = 0; i < nx; ++i) {
      const uint32_t a = uint32_t(j * (nx + 1) + i), b = a + 1, c = a + uint32_t(nx + 1), d = c + 1;
      m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
    }
  m.uvs.assign(m.positions.size(), Vec2f::Zero());
  m.compute_normals();
  test::one_part(m, Role::Ground, Material::Ground, true);
  OwnedScene s;
  s.add_instance(s.add_mesh(std::move(m)));
  Renderer renderer;
  for (double far : {60.0, 1000.0}) {
    const Camera cam = screen_camera(W, H, far);
    RenderStats stats;
    const VisibilityBuffer& vis = renderer.render_visibility(s.scene, cam, RenderOptions{}, &stats);
    uint64_t expected = 0;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const double ry = (y + 0.5 - cam.cy) / cam.fy;  // the floor is hit at z = 1 / ry
        const bool want = ry > 0.0 && 1.0 / ry <= far;
        expected += want;
        ASSERT_EQ(want, vis.instance[size_t(y) * W + size_t(x)] != kNoInstance) << x << "," << y << " far " << far;
      }
    EXPECT_GT(stats.triangles_clipped, 0u);
    EXPECT_EQ(stats.pixels_covered, expected);
    // Every fragment passes the far test when far = 1000, so fragments count coverage exactly.
    if (far > 100.0) {
      EXPECT_EQ(stats.fragments_covered, expected) << "double coverage";
    }
  }
}

TEST(RasterCoverage, TriangleFanClippedAndUnclippedCoversEachSampleOnce) {
  // A fan of 360 triangles on the floor y = 1 (view space) sharing its centre and its spokes (rim
  // radius 3 m). With the centre behind the camera every triangle is clipped at the near plane;
  // with it in front, triangles that stay in front need no clipping (SIMD setup) and those that
  // reach behind the camera do, so clipped and unclipped triangles share slanted spokes on screen.
  // Every sample whose floor point is inside the rim is covered, none outside it, none twice.
  const int W = 96, H = 64, kSpokes = 360;
  const double kRadius = 3.0, kPi = 3.14159265358979323846;
  const Camera cam = screen_camera(W, H, 1000.0);
  Renderer renderer;
  for (const double centre_z : {-0.5, 2.0}) {
    Mesh m;
    m.positions.emplace_back(0.0f, 1.0f, float(centre_z));
    for (int k = 0; k < kSpokes; ++k) {
      const double a = 2.0 * kPi * k / kSpokes;
      m.positions.emplace_back(float(kRadius * std::cos(a)), 1.0f, float(centre_z + kRadius * std::sin(a)));
    }
    for (uint32_t k = 0; k < uint32_t(kSpokes); ++k) m.indices.insert(m.indices.end(), {0u, 1u + (k + 1) % kSpokes, 1u + k});
    m.uvs.assign(m.positions.size(), Vec2f::Zero());
    m.compute_normals();
    test::one_part(m, Role::Ground, Material::Ground, true);
    OwnedScene s;
    s.add_instance(s.add_mesh(std::move(m)));
    RenderStats stats;
    const VisibilityBuffer& vis = renderer.render_visibility(s.scene, cam, RenderOptions{}, &stats);
    int inside = 0;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const double ry = (y + 0.5 - cam.cy) / cam.fy, rx = (x + 0.5 - cam.cx) / cam.fx;
        const double r = ry > 0.0 ? std::hypot(rx / ry, 1.0 / ry - centre_z) : 1e9;  // floor point's distance
        const bool hit = vis.instance[size_t(y) * W + size_t(x)] != kNoInstance;
        if (r < kRadius * std::cos(kPi / kSpokes) - 0.01) {
          ++inside;
          ASSERT_TRUE(hit) << "crack at " << x << "," << y << ", centre z " << centre_z;
        } else if (r > kRadius + 0.01) {
          ASSERT_FALSE(hit) << "outside the rim at " << x << "," << y << ", centre z " << centre_z;
        }
      }
    EXPECT_GT(inside, W * H / 8) << "centre z " << centre_z;
    EXPECT_GT(stats.triangles_clipped, 0u) << "centre z " << centre_z;
    EXPECT_EQ(stats.fragments_covered, stats.pixels_covered) << "double coverage, centre z " << centre_z;
  }
}

}  // namespace
}  // namespace silva::render
