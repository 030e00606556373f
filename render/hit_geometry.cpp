#include "render/hit_geometry.hpp"

namespace silva::render {

void HitGeometry::place(const Vec3d& p0, const Vec3d& p1, const Vec3d& p2, const Vec3d& origin) {
  p[0] = p0;
  p[1] = p1;
  p[2] = p2;
  e1 = p1 - p0;
  e2 = p2 - p0;
  s = origin - p0;
  qvec = s.cross(e1);
  e2_dot_q = e2.dot(qvec);
}

PixelHit hit_geometry(const Camera& cam, const HitGeometry& h, double ray_x, double ray_y) {
  const Vec3d origin = cam.position();
  const Vec3d dir = cam.world_direction(ray_x, ray_y);  // camera z component 1: t is metric z
  const Vec3d pvec = dir.cross(h.e2);
  const double det = h.e1.dot(pvec);
  double b1 = 1.0 / 3.0, b2 = 1.0 / 3.0, t = 0.0;
  if (det != 0.0) {
    b1 = h.s.dot(pvec) / det;
    b2 = dir.dot(h.qvec) / det;
    t = h.e2_dot_q / det;
  }
  if (!(t > 0.0)) {  // ray parallel to the triangle's plane: fall back to the centroid's depth
    const Vec3d centroid = (h.p[0] + h.p[1] + h.p[2]) / 3.0;
    t = (cam.world_to_camera().block<1, 3>(2, 0) * centroid)(0) + cam.world_to_camera()(2, 3);
    b1 = b2 = 1.0 / 3.0;
  }
  const double b0 = 1.0 - b1 - b2;
  const Vec3d hit = origin + t * dir;
  // Normal: interpolated vertex normals through the inverse transpose (cofactor matrix).
  Vec3d n = h.e1.cross(h.e2);  // without vertex normals: the geometric normal (already in world space)
  if (h.has_normals) {
    const Vec3d n_obj = b0 * h.corner_normal[0] + b1 * h.corner_normal[1] + b2 * h.corner_normal[2];
    n = h.cof * n_obj;
  }
  const double len = n.norm();
  n = len > 0.0 ? Vec3d(n / len) : Vec3d(-dir.normalized());
  if (n.dot(dir) > 0.0) n = -n;
  PixelHit out;
  out.uv = h.has_uvs ? Vec2f((b0 * h.corner_uv[0] + b1 * h.corner_uv[1] + b2 * h.corner_uv[2]).cast<float>())
                     : Vec2f::Zero();
  out.depth = float(t);
  out.position = hit.cast<float>();
  out.normal = n.cast<float>();
  out.mask_texels = float(h.mask_texels_per_metre * t / cam.fx);  // the pixel is t / fx metres wide there
  return out;
}

}  // namespace silva::render
