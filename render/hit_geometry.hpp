#pragma once
/// @file The geometry of a pixel's centre ray hitting its visible triangle (Moller-Trumbore in
/// double), one pixel at a time and on SIMD lanes for a run of pixels that see the same triangle.
#include <cstddef>
#include <cstdint>

#include "core/camera.hpp"
#include "core/types.hpp"

namespace silva::render {

/// What the hit geometry of one visible (instance, triangle) reads, prepared once for all its pixels.
struct HitGeometry {
  Vec3d p[3];                       ///< World-space corners.
  Vec3d e1, e2;                     ///< Edges p1 - p0 and p2 - p0.
  Vec3d s;                          ///< Camera origin - p0.
  Vec3d qvec;                       ///< s x e1: constant over the triangle's pixels.
  double e2_dot_q = 0;              ///< e2 . qvec (t = e2_dot_q / det).
  Mat3d cof;                        ///< Normal transform (cofactor of the instance's linear part).
  bool has_normals = false;         ///< The mesh has vertex normals (otherwise the normal is e1 x e2).
  Vec3d corner_normal[3];           ///< Object-space vertex normals, when it has them.
  bool has_uvs = false;             ///< The mesh has uvs (otherwise uv is 0).
  Eigen::Vector2d corner_uv[3];     ///< Corner uvs, when it has them.
  double mask_texels_per_metre = 0; ///< Masked part: mask texels per metre of the triangle.

  /// Sets the corners p0, p1, p2 (world space) and what follows from them and the camera's `origin`.
  void place(const Vec3d& p0, const Vec3d& p1, const Vec3d& p2, const Vec3d& origin);
};

/// What the G-buffer stores of one pixel's hit geometry.
struct PixelHit {
  float depth = 0;       ///< Metric z of the hit.
  Vec3f position;        ///< World position.
  Vec3f normal;          ///< Unit normal facing the camera (interpolated vertex normal, or geometric).
  Vec2f uv;              ///< Interpolated uv (0 without uvs).
  float mask_texels = 0; ///< Mask texels across the pixel's footprint.
};

/// The hit of the centre ray (ray_x, ray_y) (Camera::ray_x, Camera::ray_y) with h; a ray parallel to
/// or behind the triangle's plane takes the centroid's depth and barycentres, a normal without length
/// the reversed view direction.
PixelHit hit_geometry(const Camera& cam, const HitGeometry& h, double ray_x, double ray_y);

/// Most pixels one hit_geometry_run call takes (its result has a bit per pixel).
constexpr size_t kHitRunMax = 64;

/// hit_geometry of `count` (<= kHitRunMax) pixels of one row, rays ray_x[0 .. count) and ray_y, on
/// SIMD lanes: the same double operations in the same order (Eigen's association of products and dot
/// products), so the same bits, written to depth, position, normal, uv and mask_texels[0 .. count).
/// Returns bit k set where pixel k takes one of hit_geometry's fallbacks; its outputs are then
/// unspecified and the caller computes them with hit_geometry.
uint64_t hit_geometry_run(const Camera& cam, const HitGeometry& h, const double* ray_x, double ray_y, size_t count,
                          float* depth, Vec3f* position, Vec3f* normal, Vec2f* uv, float* mask_texels);

}  // namespace silva::render
