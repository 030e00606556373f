// The resolve's lane arithmetic (render/resolve_lanes.hpp) against a plain Eigen Moller-Trumbore
// written here, bit for bit, on every Highway target: random triangles and rays, rays parallel to
// a triangle, hits behind the camera, meshes without normals or uvs and a zero normal.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "core/types.hpp"
#include "highway_targets.hpp"
#include "render/resolve_lanes.hpp"

namespace silva::render {
namespace {

/// One expected pixel: z, position, normal, uv.
struct Expected {
  double t;
  Vec3d position, normal;
  Eigen::Vector2d uv;
};

/// A triangle in world space with its vertex attributes, seen from `origin`.
struct Triangle {
  Vec3d p[3];
  Vec3d normal[3];  ///< Object-space normals (used when has_normals).
  Eigen::Vector2d uv[3];
  Mat3d cof;        ///< Object-to-world normal transform.
  bool has_normals = true, has_uvs = true;
};

/// The lane record of `tri` seen from `origin` with the centroid z of `world_to_camera`.
ResolveTriangle record(const Triangle& tri, const Vec3d& origin, const Mat4d& world_to_camera) {
  ResolveTriangle r{};
  const Vec3d e1 = tri.p[1] - tri.p[0], e2 = tri.p[2] - tri.p[0], s = origin - tri.p[0], q = s.cross(e1);
  const Vec3d g = e1.cross(e2);
  const Vec3d centroid = (tri.p[0] + tri.p[1] + tri.p[2]) / 3.0;
  for (int a = 0; a < 3; ++a) {
    r.e1[a] = e1[a], r.e2[a] = e2[a], r.s[a] = s[a], r.qvec[a] = q[a], r.geometric[a] = g[a];
    for (int c = 0; c < 3; ++c) r.cof[a][c] = tri.cof(a, c);
    for (int k = 0; k < 3; ++k) r.normal[k][a] = tri.normal[k][a];
  }
  for (int k = 0; k < 3; ++k) r.uv[k][0] = tri.uv[k][0], r.uv[k][1] = tri.uv[k][1];
  r.e2_dot_q = e2.dot(q);
  r.fallback_t = (world_to_camera.block<1, 3>(2, 0) * centroid)(0) + world_to_camera(2, 3);
  r.has_normals = tri.has_normals ? 1.0 : 0.0;
  r.has_uvs = tri.has_uvs ? 1.0 : 0.0;
  return r;
}

/// The scalar resolve of one pixel ray (x, y, 1) in camera space, in Eigen.
Expected reference(const Triangle& tri, const Mat4d& camera_to_world, const Mat4d& world_to_camera, double x, double y) {
  const Vec3d origin = camera_to_world.block<3, 1>(0, 3);
  const Vec3d dir = camera_to_world.block<3, 3>(0, 0) * Vec3d(x, y, 1.0);
  const Vec3d e1 = tri.p[1] - tri.p[0], e2 = tri.p[2] - tri.p[0], s = origin - tri.p[0], qvec = s.cross(e1);
  const Vec3d pvec = dir.cross(e2);
  const double det = e1.dot(pvec);
  double b1 = 1.0 / 3.0, b2 = 1.0 / 3.0, t = 0.0;
  if (det != 0.0) {
    b1 = s.dot(pvec) / det;
    b2 = dir.dot(qvec) / det;
    t = e2.dot(qvec) / det;
  }
  if (!(t > 0.0)) {
    const Vec3d centroid = (tri.p[0] + tri.p[1] + tri.p[2]) / 3.0;
    t = (world_to_camera.block<1, 3>(2, 0) * centroid)(0) + world_to_camera(2, 3);
    b1 = b2 = 1.0 / 3.0;
  }
  const double b0 = 1.0 - b1 - b2;
  Vec3d n = e1.cross(e2);
  if (tri.has_normals) n = Vec3d(tri.cof * Vec3d(b0 * tri.normal[0] + b1 * tri.normal[1] + b2 * tri.normal[2]));
  const double len = n.norm();
  n = len > 0.0 ? Vec3d(n / len) : Vec3d(-dir.normalized());
  if (n.dot(dir) > 0.0) n = -n;
  const Eigen::Vector2d uv = tri.has_uvs ? Eigen::Vector2d(b0 * tri.uv[0] + b1 * tri.uv[1] + b2 * tri.uv[2])
                                         : Eigen::Vector2d::Zero();
  return {t, origin + t * dir, n, uv};
}

/// Bit-exact comparison of doubles (NaN never expected).
void expect_same(double want, double got, const char* what, size_t k) {
  EXPECT_EQ(std::memcmp(&want, &got, sizeof want), 0) << what << " of pixel " << k << ": " << want << " vs " << got;
}

TEST(ResolveLanes, MatchTheScalarMollerTrumboreBitForBitOnEveryTarget) {
  std::mt19937_64 gen(20261126);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto random3 = [&](double scale) -> Vec3d { return Vec3d(unit(gen), unit(gen), unit(gen)) * scale; };
  Mat4d camera_to_world = Mat4d::Identity();
  camera_to_world.block<3, 3>(0, 0) = Eigen::AngleAxisd(0.7, Vec3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  camera_to_world.block<3, 1>(0, 3) = Vec3d(12.5, -3.25, 1.75);
  const Mat4d world_to_camera = camera_to_world.inverse();
  const Vec3d origin = camera_to_world.block<3, 1>(0, 3);

  std::vector<Triangle> tris;
  for (int k = 0; k < 40; ++k) {
    Triangle tri;
    const Vec3d centre = origin + camera_to_world.block<3, 3>(0, 0) * Vec3d(unit(gen), unit(gen), 5.0 + 4.0 * unit(gen));
    for (int v = 0; v < 3; ++v) {
      tri.p[v] = centre + random3(2.0);
      tri.normal[v] = random3(1.0);
      tri.uv[v] = Eigen::Vector2d(unit(gen), unit(gen));
    }
    tri.cof = Mat3d::Identity() + Mat3d::Random() * 0.3;
    tri.has_normals = k % 5 != 1;
    tri.has_uvs = k % 7 != 2;
    tris.push_back(tri);
  }
  tris[3].p[2] = tris[3].p[0] + (tris[3].p[1] - tris[3].p[0]) * 0.5;  // degenerate: every ray parallel (det 0)
  for (Vec3d& n : tris[4].normal) n = Vec3d::Zero();                  // zero interpolated normal
  for (Vec3d& p : tris[6].p) p = origin - (p - origin);              // behind the camera: t < 0

  std::vector<ResolveTriangle> records;
  for (const Triangle& tri : tris) records.push_back(record(tri, origin, world_to_camera));
  const size_t count = 301;  // not a multiple of any target's lanes
  const size_t padded = 320;
  std::vector<int64_t> index(padded, 0);
  std::vector<double> ray_x(padded, 0.0);
  for (size_t k = 0; k < count; ++k) {
    index[k] = int64_t(gen() % tris.size());
    ray_x[k] = 0.6 * unit(gen);
  }
  const double ray_y = -0.21;
  ResolveRow row;
  row.triangles = records.data();
  row.triangle = index.data();
  row.ray_x = ray_x.data();
  row.ray_y = ray_y;
  row.count = count;
  for (int a = 0; a < 3; ++a) {
    row.origin[a] = origin[a];
    for (int c = 0; c < 3; ++c) row.rotation[a][c] = camera_to_world(a, c);
  }
  for (int64_t target : test::highway_targets()) {
    const test::PinnedTarget pin(target);
    SCOPED_TRACE(hwy::TargetName(target));
    ASSERT_LE(resolve_lane_padding(), 16u);
    std::vector<double> t(padded), px(padded), py(padded), pz(padded), nx(padded), ny(padded), nz(padded), u(padded),
        v(padded);
    resolve_hits_lanes(row, {t.data(), {px.data(), py.data(), pz.data()}, {nx.data(), ny.data(), nz.data()},
                             {u.data(), v.data()}});
    for (size_t k = 0; k < count; ++k) {
      const Expected e = reference(tris[size_t(index[k])], camera_to_world, world_to_camera, ray_x[k], ray_y);
      expect_same(e.t, t[k], "t", k);
      expect_same(e.position.x(), px[k], "x", k);
      expect_same(e.position.y(), py[k], "y", k);
      expect_same(e.position.z(), pz[k], "z", k);
      expect_same(e.normal.x(), nx[k], "nx", k);
      expect_same(e.normal.y(), ny[k], "ny", k);
      expect_same(e.normal.z(), nz[k], "nz", k);
      expect_same(e.uv.x(), u[k], "u", k);
      expect_same(e.uv.y(), v[k], "v", k);
      EXPECT_NEAR(nx[k] * nx[k] + ny[k] * ny[k] + nz[k] * nz[k], 1.0, 1e-12) << k;
    }
  }
}

}  // namespace
}  // namespace silva::render
