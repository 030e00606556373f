#pragma once
/// @file Hand-made G-buffers and shadow maps for the shading tests (ray-cast, no rasteriser).
#include <cmath>
#include <limits>

#include "core/camera.hpp"
#include "render/gbuffer.hpp"

namespace silva::render::test {

/// A w x h camera 1.5 m above the origin looking along +X, pitched down by `pitch_deg`.
inline Camera test_camera(int w, int h, double pitch_deg) {
  Camera cam = Camera::from_fov(w, h, 90, 0.05, 150);
  cam.camera_to_world = pose_from_angles(Vec3d(0, 0, 1.5), 0, -pitch_deg, 0);
  return cam;
}

/// G-buffer of the ground plane z = 0 (material `m`) seen by `cam`; rays that miss it see sky.
/// A vertical wall x = wall_x (material Rock) is added when wall_x > 0.
inline GBuffer plane_gbuffer(const Camera& cam, Material m, double wall_x = 0) {
  GBuffer g;
  g.resize(cam.width, cam.height);
  const Vec3d o = cam.position();
  for (int v = 0; v < cam.height; ++v) {
    for (int u = 0; u < cam.width; ++u) {
      const Vec3d d = cam.ray_direction(u, v);  // camera z = 1, so t is the depth
      double t = d.z() < 0 ? -o.z() / d.z() : std::numeric_limits<double>::infinity();
      Vec3d n(0, 0, 1);
      Material mat = m;
      if (wall_x > 0 && d.x() > 0) {
        const double tw = (wall_x - o.x()) / d.x();
        if (tw < t) {
          t = tw;
          n = Vec3d(-1, 0, 0);
          mat = Material::Rock;
        }
      }
      if (!(t < cam.far)) continue;
      const size_t i = size_t(v) * size_t(cam.width) + size_t(u);
      g.depth[i] = float(t);
      g.position[i] = (o + t * d).cast<float>();
      g.normal[i] = n.cast<float>();
      g.material[i] = mat;
      g.role[i] = Role::Ground;
      g.variation[i] = 7;
    }
  }
  return g;
}

/// World -> light rotation for a sun direction (light +z travels away from the sun).
inline Mat4d light_frame(const Vec3d& to_sun) {
  const Vec3d z = -to_sun.normalized();
  const Vec3d h = std::abs(z.z()) > 0.99 ? Vec3d::UnitX() : Vec3d::UnitZ();
  const Vec3d x = h.cross(z).normalized();
  const Vec3d y = z.cross(x);
  Mat4d m = Mat4d::Identity();
  m.block<1, 3>(0, 0) = x.transpose();
  m.block<1, 3>(1, 0) = y.transpose();
  m.block<1, 3>(2, 0) = z.transpose();
  return m;
}

/// Shadow map n x n texels of `texel` metres centred on the light-space origin, holding the
/// ground plane z = 0 plus, if occluder_half > 0, a horizontal square |x|,|y| <= occluder_half
/// at height occluder_z (depths computed analytically along each texel-centre ray).
inline ShadowMap plane_shadow_map(const Vec3d& to_sun, int n, double texel, double occluder_half = 0,
                                  double occluder_z = 0) {
  ShadowMap map;
  map.width = map.height = n;
  map.texel_size = texel;
  map.origin_x = map.origin_y = -0.5 * n * texel;
  map.world_to_light = light_frame(to_sun);
  const Mat3d r = map.world_to_light.block<3, 3>(0, 0);
  const Vec3d along = r.row(2).transpose();  // world direction of light +z
  map.depth.assign(size_t(n) * size_t(n), std::numeric_limits<float>::infinity());
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const Vec3d l(map.origin_x + (x + 0.5) * texel, map.origin_y + (y + 0.5) * texel, 0.0);
      const Vec3d w0 = r.transpose() * l;  // world point at light z = 0
      double depth = -w0.z() / along.z();  // hit of z = 0
      if (occluder_half > 0) {
        const double t = (occluder_z - w0.z()) / along.z();
        const Vec3d p = w0 + t * along;
        if (std::abs(p.x()) <= occluder_half && std::abs(p.y()) <= occluder_half && t < depth) depth = t;
      }
      map.depth[size_t(y) * size_t(n) + size_t(x)] = float(depth);
    }
  }
  return map;
}

}  // namespace silva::render::test
