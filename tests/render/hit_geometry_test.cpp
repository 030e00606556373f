#include "render/hit_geometry.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <random>
#include <vector>

#include "highway_targets.hpp"

namespace silva::render {
namespace {

/// Bits of a float, so that equal means the same bits (and NaN equals itself).
uint32_t bits(float f) { return std::bit_cast<uint32_t>(f); }

/// A HitGeometry for corners p seen from `origin`, with normals and uvs as given (empty: none).
HitGeometry triangle(const Vec3d (&p)[3], const Vec3d& origin, const Mat3d& cof, const std::vector<Vec3d>& normals,
                     const std::vector<Eigen::Vector2d>& uvs) {
  HitGeometry h;
  h.place(p[0], p[1], p[2], origin);
  h.cof = cof;
  h.has_normals = !normals.empty();
  h.has_uvs = !uvs.empty();
  for (int k = 0; k < 3; ++k) {
    if (h.has_normals) h.corner_normal[k] = normals[size_t(k)];
    if (h.has_uvs) h.corner_uv[k] = uvs[size_t(k)];
  }
  h.mask_texels_per_metre = 37.5;
  return h;
}

/// Pixels of row v whose lane result (or, where flagged, hit_geometry's) differs from hit_geometry in any bit.
size_t differing_pixels(const Camera& cam, const HitGeometry& h, int v, size_t* flagged = nullptr) {
  std::vector<double> ray_x(size_t(cam.width));
  for (int u = 0; u < cam.width; ++u) ray_x[size_t(u)] = cam.ray_x(u);
  size_t differing = 0;
  for (size_t first = 0; first < ray_x.size(); first += kHitRunMax) {
    const size_t count = std::min(kHitRunMax, ray_x.size() - first);
    std::vector<float> depth(count), texels(count);
    std::vector<Vec3f> position(count), normal(count);
    std::vector<Vec2f> uv(count);
    const uint64_t fallback = hit_geometry_run(cam, h, &ray_x[first], cam.ray_y(v), count, depth.data(),
                                               position.data(), normal.data(), uv.data(), texels.data());
    for (size_t k = 0; k < count; ++k) {
      const PixelHit want = hit_geometry(cam, h, ray_x[first + k], cam.ray_y(v));
      if ((fallback >> k) & 1) {
        if (flagged) ++*flagged;
        continue;
      }
      bool same = bits(depth[k]) == bits(want.depth) && bits(texels[k]) == bits(want.mask_texels);
      for (int c = 0; c < 3; ++c)
        same = same && bits(position[k][c]) == bits(want.position[c]) && bits(normal[k][c]) == bits(want.normal[c]);
      for (int c = 0; c < 2; ++c) same = same && bits(uv[k][c]) == bits(want.uv[c]);
      differing += same ? 0 : 1;
    }
  }
  return differing;
}

TEST(HitGeometry, AFrontFacingTriangleHasItsPlanesDepthAndFacesTheCamera) {
  Camera cam = Camera::from_fov(64, 48, 90, 0.05, 150);
  cam.camera_to_world = pose_from_angles(Vec3d(0, 0, 0), 0, 0, 0);
  // A big triangle 5 m in front of the camera, across the view axis.
  const Vec3d forward = cam.world_direction(0, 0), right = cam.world_direction(1, 0) - forward,
              down = cam.world_direction(0, 1) - forward;
  const Vec3d p[3] = {5 * forward - 20 * right - 20 * down, 5 * forward + 20 * right - 20 * down,
                      5 * forward + 20 * down};
  const HitGeometry h = triangle(p, cam.position(), Mat3d::Identity(), {}, {});
  const PixelHit hit = hit_geometry(cam, h, cam.ray_x(10), cam.ray_y(30));
  EXPECT_NEAR(hit.depth, 5.0f, 1e-5f);
  EXPECT_LT(hit.normal.cast<double>().dot(cam.world_direction(cam.ray_x(10), cam.ray_y(30))), 0.0);
  EXPECT_NEAR(hit.normal.norm(), 1.0f, 1e-6f);
  EXPECT_EQ(differing_pixels(cam, h, 30), 0u);
}

TEST(HitGeometry, LanesMatchOnePixelAtATimeOnEveryHighwayTarget) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto random3 = [&] { return Vec3d(unit(rng), unit(rng), unit(rng)); };
  for (int64_t target : test::highway_targets()) {
    SCOPED_TRACE(hwy::TargetName(target));
    const test::PinnedTarget pin(target);
    size_t differing = 0, flagged = 0, rows = 0;
    for (int trial = 0; trial < 60; ++trial) {
      Camera cam = Camera::from_fov(101 + trial, 37, 70 + trial, 0.05, 150);
      cam.camera_to_world = pose_from_angles(3 * random3(), 180 * unit(rng), 60 * unit(rng), 10 * unit(rng));
      const Vec3d ahead = cam.position() + 4 * cam.world_direction(0.2 * unit(rng), 0.2 * unit(rng));
      const Vec3d p[3] = {ahead + 3 * random3(), ahead + 3 * random3(), ahead + 3 * random3()};
      Mat3d cof = Mat3d::Identity() + 0.5 * Mat3d::Random();
      const bool normals = trial % 3 != 0, uvs = trial % 4 != 0;
      const HitGeometry h = triangle(p, cam.position(), cof, normals ? std::vector{random3(), random3(), random3()}
                                                                         : std::vector<Vec3d>{},
                                     uvs ? std::vector{Eigen::Vector2d::Random().eval(), Eigen::Vector2d::Random().eval(),
                                                       Eigen::Vector2d::Random().eval()}
                                         : std::vector<Eigen::Vector2d>{});
      for (int v = 0; v < cam.height; v += 4, ++rows) differing += differing_pixels(cam, h, v, &flagged);
    }
    EXPECT_EQ(differing, 0u);
    // Random triangles around a point ahead: most pixels miss their plane behind the camera or not at all.
    EXPECT_GT(flagged, 0u);
    EXPECT_GT(rows, 0u);
  }
}

TEST(HitGeometry, LanesSumTheNormalTransformInEigensOrder) {
  // Corner normals with equal components and a transform whose rows cancel in one association only:
  // rows 0 and 1 give z when summed left to right (0 otherwise), row 2 gives x when summed as
  // m20 x + (m21 y + m22 z) (0 otherwise). Random inputs rarely show an association in float bits.
  Mat3d cof;
  cof << 1e17, -1e17, 1, 1e17, -1e17, 1, 1, 1e17, -1e17;
  Camera cam = Camera::from_fov(90, 9, 80, 0.05, 150);
  cam.camera_to_world = pose_from_angles(Vec3d(1, 2, 3), 30, -10, 0);
  const Vec3d ahead = cam.position() + 4 * cam.world_direction(0, 0);
  const Vec3d p[3] = {ahead + Vec3d(-5, -5, -5), ahead + Vec3d(5, -5, 5), ahead + Vec3d(0, 5, 0)};
  const HitGeometry h = triangle(p, cam.position(), cof, {Vec3d(1, 1, 1), Vec3d(2, 2, 2), Vec3d(0.5, 0.5, 0.5)}, {});
  ASSERT_NEAR(hit_geometry(cam, h, cam.ray_x(45), cam.ray_y(4)).normal.cwiseAbs().minCoeff(), 1 / std::sqrt(3.0f), 1e-6f);
  for (int64_t target : test::highway_targets()) {
    SCOPED_TRACE(hwy::TargetName(target));
    const test::PinnedTarget pin(target);
    size_t flagged = 0;
    EXPECT_EQ(differing_pixels(cam, h, 4, &flagged), 0u);
    EXPECT_LT(flagged, size_t(cam.width));
  }
}

TEST(HitGeometry, RaysParallelOrBehindAndNormalsWithoutLengthAreFlagged) {
  Camera cam = Camera::from_fov(40, 8, 80, 0.05, 150);
  cam.camera_to_world = pose_from_angles(Vec3d(1, 2, 3), 30, 0, 0);
  const Vec3d behind = cam.position() - 4 * cam.world_direction(0, 0);
  const Vec3d back[3] = {behind + Vec3d(1, 0, 0), behind + Vec3d(0, 1, 0), behind + Vec3d(0, 0, 1)};
  const Vec3d ahead = cam.position() + 4 * cam.world_direction(0, 0);
  const Vec3d line[3] = {ahead, ahead + Vec3d(1, 0, 0), ahead + Vec3d(2, 0, 0)};  // no area: det is 0
  for (const auto* p : {&back, &line}) {
    const HitGeometry h = triangle(*p, cam.position(), Mat3d::Identity(), {}, {});
    size_t flagged = 0;
    EXPECT_EQ(differing_pixels(cam, h, 3, &flagged), 0u);
    EXPECT_EQ(flagged, size_t(cam.width));
  }
  // Normals that cancel at the pixels' barycentres: the normal has no length there.
  const Vec3d p[3] = {ahead + Vec3d(-9, -9, -9), ahead + Vec3d(9, -9, 9), ahead + Vec3d(0, 9, 0)};
  const HitGeometry zero = triangle(p, cam.position(), Mat3d::Zero(), {Vec3d(0, 0, 1), Vec3d(0, 0, 1), Vec3d(0, 0, 1)}, {});
  size_t flagged = 0;
  EXPECT_EQ(differing_pixels(cam, zero, 3, &flagged), 0u);
  EXPECT_GT(flagged, 0u);
}

}  // namespace
}  // namespace silva::render
