#include "render/view_projection.hpp"

#include <cmath>
#include <limits>

#include "render/raster_conventions.hpp"

namespace silva::render {

namespace {

/// Converts a plane over continuous (u, v) into one over pixel indices (centre at +0.5).
PixelPlane to_pixel_plane(double c, double a, double b) {
  return PixelPlane{c + 0.5 * a + 0.5 * b, a, b};
}

}  // namespace

ViewProjection ViewProjection::from_camera(const Camera& camera) {
  ViewProjection v;
  v.perspective = true;
  v.width = camera.width;
  v.height = camera.height;
  v.world_to_view = camera.world_to_camera();
  v.fx = camera.fx;
  v.fy = camera.fy;
  v.cx = camera.cx;
  v.cy = camera.cy;
  v.near = camera.near;
  v.far = camera.far;
  return v;
}

ViewProjection ViewProjection::orthographic(const Mat4d& world_to_view, double origin_x, double origin_y,
                                            double texel_size, int width, int height) {
  ViewProjection v;
  v.perspective = false;
  v.width = width;
  v.height = height;
  v.world_to_view = world_to_view;
  v.fx = v.fy = 1.0 / texel_size;
  v.cx = -origin_x / texel_size;
  v.cy = -origin_y / texel_size;
  v.near = -std::numeric_limits<double>::infinity();
  v.far = std::numeric_limits<double>::infinity();
  return v;
}

Vec2d ViewProjection::project(const Vec3d& p) const {
  if (perspective) return Vec2d(fx * p.x() / p.z() + cx, fy * p.y() / p.z() + cy);
  return Vec2d(fx * p.x() + cx, fy * p.y() + cy);
}

double ViewProjection::depth_clear() const {
  return perspective ? 1.0 / far : -std::numeric_limits<double>::infinity();
}

Vec4d ViewProjection::bound_plane(int axis, double limit, bool upper) const {
  const double f = axis == 0 ? fx : fy;
  const double c = axis == 0 ? cx : cy;
  const double s = upper ? -1.0 : 1.0;  // u >= L  <=>  s*(u - L) >= 0
  Vec4d p = Vec4d::Zero();
  p[axis] = s * f;
  if (perspective) {
    p[2] = s * (c - limit);  // s*(f*x + (c - L)*z) >= 0 with z > 0
  } else {
    p[3] = s * (c - limit);
  }
  return p;
}

int ViewProjection::frustum_planes(Vec4d out[6]) const {
  int n = 0;
  out[n++] = bound_plane(0, 0.0, false);
  out[n++] = bound_plane(0, double(width), true);
  out[n++] = bound_plane(1, 0.0, false);
  out[n++] = bound_plane(1, double(height), true);
  if (perspective) {
    out[n++] = Vec4d(0, 0, 1, -near);
    out[n++] = Vec4d(0, 0, -1, far);
  }
  return n;
}

int ViewProjection::clip_planes(Vec4d out[5]) const {
  int n = 0;
  if (perspective) out[n++] = Vec4d(0, 0, 1, -near);
  out[n++] = bound_plane(0, -kGuardBandPixels, false);
  out[n++] = bound_plane(0, double(width) + kGuardBandPixels, true);
  out[n++] = bound_plane(1, -kGuardBandPixels, false);
  out[n++] = bound_plane(1, double(height) + kGuardBandPixels, true);
  return n;
}

PixelScales ViewProjection::pixel_scales() const { return PixelScales{1.0 / fx, 1.0 / fy, cx / fx, cy / fy}; }

PixelPlane ViewProjection::depth_plane(const Vec3d& p0, const Vec3d& n, const PixelScales& s) const {
  if (perspective) {
    // Ray r(u,v) = (r0 + u*ru + v*rv) hits the plane at t = (p0.n)/(r.n); z = t, d = (r.n)/(p0.n).
    const double inv_k = 1.0 / dot3(p0, n);
    const double c = (n.z() - n.x() * s.cx_fx - n.y() * s.cy_fy) * inv_k;
    return to_pixel_plane(c, n.x() * s.inv_fx * inv_k, n.y() * s.inv_fy * inv_k);
  }
  // Ray from O(u,v) = ((u-cx)/fx, (v-cy)/fy, 0) along +z: z = p0.z - ((O - p0)_xy . n_xy) / n.z.
  // d = -z = ((O - p0) . n) / n.z, with O.z = 0.
  const double inv_nz = 1.0 / n.z();
  const double c = (-s.cx_fx * n.x() - s.cy_fy * n.y() - dot3(p0, n)) * inv_nz;
  return to_pixel_plane(c, n.x() * s.inv_fx * inv_nz, n.y() * s.inv_fy * inv_nz);
}

void ViewProjection::barycentric_planes(const Vec3d& p0, const Vec3d& p1, const Vec3d& p2, const PixelScales& s,
                                        PixelPlane& n1, PixelPlane& n2, PixelPlane& den) const {
  // Moller-Trumbore with s = O - p0: b1 = s.(r x e2)/det, b2 = r.(s x e1)/det, det = e1.(r x e2).
  const Vec3d e1 = p1 - p0, e2 = p2 - p0;
  if (perspective) {
    // O = 0: every term is linear in r(u,v) = (r0 + u*ru + v*rv): value = r . q.
    const Vec3d o = -p0;
    const Vec3d q1 = cross3(e2, o), q2 = cross3(o, e1), qd = cross3(e2, e1);
    const auto plane = [&](const Vec3d& q) {
      return to_pixel_plane(q.z() - q.x() * s.cx_fx - q.y() * s.cy_fy, q.x() * s.inv_fx, q.y() * s.inv_fy);
    };
    n1 = plane(q1);
    n2 = plane(q2);
    den = plane(qd);
    return;
  }
  // r = (0,0,1): every term is linear in o(u,v) = O(u,v) - p0: value = o . w.
  const Vec3d r(0, 0, 1);
  const Vec3d w1 = cross3(r, e2), w2 = cross3(e1, r);
  const auto plane = [&](const Vec3d& w) {
    return to_pixel_plane(-s.cx_fx * w.x() - s.cy_fy * w.y() - dot3(p0, w), w.x() * s.inv_fx, w.y() * s.inv_fy);
  };
  n1 = plane(w1);
  n2 = plane(w2);
  den = PixelPlane{dot3(e1, cross3(r, e2)), 0.0, 0.0};
}

double ViewProjection::screen_size(double radius, double distance) const {
  if (!perspective) return 2.0 * radius * fy / double(height);
  if (distance <= radius) return std::numeric_limits<double>::infinity();
  return 2.0 * radius * fy / (distance * double(height));
}

}  // namespace silva::render
