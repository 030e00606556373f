// Shadow map: a floating quad's known footprint on the ground, in light space.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "raster_test_scenes.hpp"
#include "render/renderer.hpp"
#include "render/shadow_pass.hpp"

namespace silva::render {
namespace {

/// Light-space z of a world point.
double light_z(const ShadowMap& m, const Vec3d& p) { return (m.world_to_light.topLeftCorner<3, 3>() * p)(2); }

/// Depth stored at the texel containing world point p.
float texel_depth(const ShadowMap& m, const Vec3d& p) {
  const Vec3d l = m.world_to_light.topLeftCorner<3, 3>() * p;
  const int x = int(std::floor((l.x() - m.origin_x) / m.texel_size));
  const int y = int(std::floor((l.y() - m.origin_y) / m.texel_size));
  return m.depth[size_t(y) * size_t(m.width) + size_t(x)];
}

TEST(RasterShadow, OblongFootprintGetsAnOblongMapOfSquareTexels) {
  AABB region;  // 40 m x 10 m, flat, seen from straight above
  region.extend(Vec3f(-20, -5, 0));
  region.extend(Vec3f(20, 5, 0));
  const ShadowMap map = shadow_map_frame(Vec3d(0, 0, 1), region, 256);
  EXPECT_DOUBLE_EQ(map.texel_size, 40.0 / 256.0);
  EXPECT_EQ(std::max(map.width, map.height), 256);
  EXPECT_EQ(std::min(map.width, map.height), 64);  // 10 m / (40 m / 256)
  for (int c = 0; c < 4; ++c) {  // every corner of the region lies on the texel grid
    const Vec3d p((c & 1) ? 20 : -20, (c & 2) ? 5 : -5, 0);
    const Vec3d l = map.world_to_light.topLeftCorner<3, 3>() * p;
    EXPECT_GE(l.x(), map.origin_x - 1e-9);
    EXPECT_LE(l.x(), map.origin_x + map.width * map.texel_size + 1e-9);
    EXPECT_GE(l.y(), map.origin_y - 1e-9);
    EXPECT_LE(l.y(), map.origin_y + map.height * map.texel_size + 1e-9);
  }
}

TEST(RasterShadow, FloatingQuadCastsItsFootprintOnTheGround) {
  test::OwnedScene s;
  s.add_instance(s.add_mesh(test::make_quad({-10, -10, 0}, {10, -10, 0}, {10, 10, 0}, {-10, 10, 0}, Role::Ground)));
  s.add_instance(s.add_mesh(test::make_quad({-1, -1, 2}, {1, -1, 2}, {1, 1, 2}, {-1, 1, 2}, Role::Obstacle)));
  const Vec3d to_sun(0.3, 0.2, 1.0);
  AABB region;
  region.extend(Vec3f(-10, -10, 0));
  region.extend(Vec3f(10, 10, 2));
  Renderer renderer;
  const ShadowMap map = renderer.render_shadow_map(s.scene, to_sun, region, 256, RenderOptions{});
  ASSERT_EQ(std::max(map.width, map.height), 256);  // the footprint's longer side
  ASSERT_EQ(map.depth.size(), size_t(map.width) * size_t(map.height));
  // Light space is a rotation with +z pointing away from the sun.
  const Mat3d r = map.world_to_light.topLeftCorner<3, 3>();
  EXPECT_TRUE((r * r.transpose()).isIdentity(1e-12));
  EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
  EXPECT_TRUE(r.row(2).transpose().isApprox(-to_sun.normalized(), 1e-12));

  const Vec3d xw = r.row(0).transpose(), yw = r.row(1).transpose(), zw = r.row(2).transpose();
  int quad_texels = 0, ground_texels = 0, empty_texels = 0, footprint_texels = 0;
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      const double lx = map.origin_x + (x + 0.5) * map.texel_size, ly = map.origin_y + (y + 0.5) * map.texel_size;
      // The texel centre's ray W(s) = lx*xw + ly*yw + s*zw meets the plane z = h at s(h).
      const auto s_at = [&](double h) { return (h - lx * xw.z() - ly * yw.z()) / zw.z(); };
      const auto world = [&](double sv) { return Vec3d(lx * xw + ly * yw + sv * zw); };
      const double margin = 2.0 * map.texel_size;
      const Vec3d on_quad = world(s_at(2.0)), on_ground = world(s_at(0.0));
      footprint_texels += std::abs(map.depth[size_t(y) * size_t(map.width) + size_t(x)] - s_at(2.0)) < 1e-3;
      const double dq = 1.0 - on_quad.head<2>().cwiseAbs().maxCoeff();  // > 0 inside the quad
      const double dg = 10.0 - on_ground.head<2>().cwiseAbs().maxCoeff();
      if (std::abs(dq) < margin || std::abs(dg) < margin) continue;
      const float got = map.depth[size_t(y) * size_t(map.width) + size_t(x)];
      if (dq > 0) {
        ASSERT_NEAR(got, s_at(2.0), 1e-4) << x << "," << y;
        ++quad_texels;
      } else if (dg > 0) {
        ASSERT_NEAR(got, s_at(0.0), 1e-4) << x << "," << y;
        ++ground_texels;
      } else {
        ASSERT_TRUE(std::isinf(got) && got > 0) << x << "," << y;
        ++empty_texels;
      }
    }
  // The footprint of a 2 m x 2 m quad seen along the light: 4 m^2 * cos(angle) / texel area.
  const double footprint = 4.0 * std::abs(zw.z()) / (map.texel_size * map.texel_size);
  EXPECT_NEAR(footprint_texels, footprint, 0.1 * footprint);
  EXPECT_GT(quad_texels, 150);
  EXPECT_GT(ground_texels, 5000);
  EXPECT_GT(empty_texels, 100);
  // A ground point straight "below" the quad along the light is shadowed; a far one is lit.
  const Vec3d shadowed(-0.6, -0.4, 0.0), lit(5.0, 5.0, 0.0);
  EXPECT_GT(light_z(map, shadowed), double(texel_depth(map, shadowed)) + 0.5);
  EXPECT_NEAR(light_z(map, lit), double(texel_depth(map, lit)), 0.05);
}

TEST(RasterShadow, ShadowPassDrawsTheShadowCasterAndTheCameraPassTheLevels) {
  // The mesh: two 2 m quads at z = 2 (4 triangles); its caster: one 6 m quad at z = 2 (2 triangles).
  Mesh levels = test::make_quad({-1, -1, 2}, {1, -1, 2}, {1, 1, 2}, {-1, 1, 2}, Role::TreeCanopy);
  levels.append(test::make_quad({-1, 5, 2}, {1, 5, 2}, {1, 7, 2}, {-1, 7, 2}, Role::TreeCanopy));
  const Mesh caster = test::make_quad({-3, -3, 2}, {3, -3, 2}, {3, 3, 2}, {-3, 3, 2}, Role::TreeCanopy);
  test::OwnedScene s;
  s.add_instance(s.add_mesh(test::make_quad({-10, -10, 0}, {10, -10, 0}, {10, 10, 0}, {-10, 10, 0}, Role::Ground)));
  const uint32_t tree = s.add_mesh(levels);
  s.scene.meshes[tree].shadow_caster = &caster;
  s.scene.meshes[tree].compute_bounds();
  s.add_instance(tree);
  AABB region;
  region.extend(Vec3f(-10, -10, 0));
  region.extend(Vec3f(10, 10, 2));
  Renderer renderer;
  const ShadowMap map = renderer.render_shadow_map(s.scene, Vec3d(0, 0, 1), region, 200, RenderOptions{});
  const Vec3d under_caster_only(2.5, 0, 0), under_both(0, 0, 0), under_second_quad(0, 6, 0);
  EXPECT_NEAR(light_z(map, under_caster_only) - double(texel_depth(map, under_caster_only)), 2.0, 1e-3);
  EXPECT_NEAR(light_z(map, under_both) - double(texel_depth(map, under_both)), 2.0, 1e-3);
  EXPECT_NEAR(light_z(map, under_second_quad), double(texel_depth(map, under_second_quad)), 1e-3);

  // The camera, 10 m above looking straight down, sees the levels: ground at (2.5, 0), a quad at (0, 6, 2).
  Camera cam = Camera::from_fov(200, 200, 90.0, 0.05, 100.0);
  cam.camera_to_world = pose_from_angles(Vec3d(0, 0, 10), 0, -90, 0);
  const VisibilityBuffer& vis = renderer.render_visibility(s.scene, cam, RenderOptions{});
  const Mat4d to_cam = cam.world_to_camera();
  const auto instance_at = [&](double x, double y, double z) {
    const Vec3d c = to_cam.topLeftCorner<3, 3>() * Vec3d(x, y, z) + to_cam.block<3, 1>(0, 3);
    const int u = int(cam.fx * c.x() / c.z() + cam.cx), v = int(cam.fy * c.y() / c.z() + cam.cy);
    return vis.instance[size_t(v) * size_t(vis.width) + size_t(u)];
  };
  EXPECT_EQ(instance_at(2.5, 0, 0), 0u);
  EXPECT_EQ(instance_at(0, 6, 2), 1u);
}

TEST(RasterShadow, BadShadowInputIsAnInputError) {
  test::OwnedScene s;
  AABB region;
  region.extend(Vec3f(0, 0, 0));
  region.extend(Vec3f(1, 1, 1));
  Renderer r;
  EXPECT_THROW(r.render_shadow_map(s.scene, Vec3d::Zero(), region, 64, RenderOptions{}), InputError);
  EXPECT_THROW(r.render_shadow_map(s.scene, Vec3d(0, 0, 1), AABB{}, 64, RenderOptions{}), InputError);
  EXPECT_THROW(r.render_shadow_map(s.scene, Vec3d(0, 0, 1), region, 0, RenderOptions{}), InputError);
  const ShadowMap m = render_shadow_map(s.scene, Vec3d(0, 0, 1), region, 8, RenderOptions{});
  for (float d : m.depth) EXPECT_EQ(d, std::numeric_limits<float>::infinity());
}

}  // namespace
}  // namespace silva::render
