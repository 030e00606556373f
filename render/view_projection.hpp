#pragma once
/// @file How a view maps world space to pixels: the perspective camera or the orthographic sun.
#include <Eigen/Core>

#include "core/camera.hpp"
#include "core/types.hpp"

namespace silva::render {

using Vec2d = Eigen::Vector2d;  ///< 2D double vector.
using Vec4d = Eigen::Vector4d;  ///< Plane (a, b, c, d): a*x + b*y + c*z + d >= 0 is inside.

/// a x b with a fixed operation order, which the SIMD triangle setup repeats lane by lane.
inline Vec3d cross3(const Vec3d& a, const Vec3d& b) {
  return Vec3d(a.y() * b.z() - a.z() * b.y(), a.z() * b.x() - a.x() * b.z(), a.x() * b.y() - a.y() * b.x());
}

/// a . b with a fixed operation order, (ax bx + ay by) + az bz (Eigen's dot may sum in another order).
inline double dot3(const Vec3d& a, const Vec3d& b) { return (a.x() * b.x() + a.y() * b.y()) + a.z() * b.z(); }

/// An affine function of pixel-index coordinates: value(x, y) = (c + b*y) + a*x.
struct PixelPlane {
  double c = 0;  ///< Value at pixel (0, 0)'s centre.
  double a = 0;  ///< Change per pixel to the right.
  double b = 0;  ///< Change per pixel down.
  /// Value at pixel (x, y)'s centre, evaluated in the rasteriser's fixed order.
  double at(double x, double y) const { return (c + b * y) + a * x; }
};

/// Reciprocals of a view's pixel mapping, computed once per pass so that setting up a triangle's
/// planes divides at most once (by its own plane constant) instead of by fx and fy every time.
struct PixelScales {
  double inv_fx = 1, inv_fy = 1;  ///< 1 / fx, 1 / fy.
  double cx_fx = 0, cy_fy = 0;    ///< cx / fx, cy / fy.
};

/// A view: world -> view transform plus a perspective or orthographic projection (see
/// raster_conventions.hpp for axes and depth).
struct ViewProjection {
  bool perspective = true;   ///< false: orthographic.
  int width = 0;             ///< Pixels across.
  int height = 0;            ///< Pixels down.
  Mat4d world_to_view = Mat4d::Identity();  ///< World -> view space (rigid).
  double fx = 1, fy = 1;     ///< Perspective: focal lengths; orthographic: pixels per metre.
  double cx = 0, cy = 0;     ///< u = fx*x/z + cx (perspective) or u = fx*x + cx (orthographic).
  double near = 0.05;        ///< Perspective near plane (view z).
  double far = 150.0;        ///< Perspective far plane (view z).

  /// The perspective view of a camera.
  static ViewProjection from_camera(const Camera& camera);
  /// An orthographic view: texel (x, y) covers view x in [origin_x + x*texel, +texel), same for y.
  static ViewProjection orthographic(const Mat4d& world_to_view, double origin_x, double origin_y,
                                     double texel_size, int width, int height);

  /// Continuous screen position (u, v) of a view-space point (perspective needs z > 0).
  Vec2d project(const Vec3d& p) const;
  /// Reverse depth value d of a view-space point (1/z or -z).
  double depth_value(const Vec3d& p) const { return perspective ? 1.0 / p.z() : -p.z(); }
  /// Depth value every pixel starts with; samples must beat it (1/far, or -inf).
  double depth_clear() const;
  /// Sign test of raster_conventions.hpp: negative for a front face seen from this view.
  double facing(const Vec3d& p0, const Vec3d& n) const { return perspective ? dot3(p0, n) : n.z(); }
  /// Planes of the visible volume (image sides, plus near and far for perspective); returns count.
  int frustum_planes(Vec4d out[6]) const;
  /// Planes a drawn triangle is clipped against (near plane, guard band); returns count.
  int clip_planes(Vec4d out[5]) const;
  /// The reciprocals depth_plane and barycentric_planes multiply by.
  PixelScales pixel_scales() const;
  /// Plane of the reverse depth d over pixels for the triangle's plane (p0 on it, normal n);
  /// `s` = pixel_scales().
  PixelPlane depth_plane(const Vec3d& p0, const Vec3d& n, const PixelScales& s) const;
  /// Homogeneous barycentrics: b1 = n1/den, b2 = n2/den at each pixel centre (planes scaled alike,
  /// so the ratios are the barycentrics); `s` = pixel_scales().
  void barycentric_planes(const Vec3d& p0, const Vec3d& p1, const Vec3d& p2, const PixelScales& s, PixelPlane& n1,
                          PixelPlane& n2, PixelPlane& den) const;
  /// Projected diameter of a world sphere of radius r at distance `distance`, as a fraction of
  /// the image height (LOD selection).
  double screen_size(double radius, double distance) const;

 private:
  /// Plane for "u >= limit" (axis 0) or "v >= limit" (axis 1), or "<=" when upper is true.
  Vec4d bound_plane(int axis, double limit, bool upper) const;
};

}  // namespace silva::render
