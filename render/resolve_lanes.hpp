#pragma once
/// @file The per-pixel arithmetic of the G-buffer resolve on Highway SIMD lanes (runtime
/// dispatch): a row's hit pixels re-intersected with their triangles, several pixels at once.
#include <cstddef>
#include <cstdint>

namespace silva::render {

/// One visible triangle as the lanes read it (world space, doubles; gathered per lane, so the
/// fields are plain doubles at fixed offsets).
struct ResolveTriangle {
  double e1[3];          ///< Edge p1 - p0.
  double e2[3];          ///< Edge p2 - p0.
  double s[3];           ///< Camera origin - p0.
  double qvec[3];        ///< s x e1.
  double e2_dot_q;       ///< e2 . qvec (t = e2_dot_q / det).
  double fallback_t;     ///< Metric z of the centroid, for rays parallel to the triangle.
  double cof[3][3];      ///< Normal transform (cofactor of the instance's linear part), [row][column].
  double normal[3][3];   ///< Object-space vertex normals [vertex][axis] (has_normals).
  double uv[3][2];       ///< Vertex texture coordinates [vertex][axis] (has_uvs).
  double geometric[3];   ///< e1 x e2: the world-space normal of meshes without vertex normals.
  double has_normals;    ///< 1 when `normal` holds the mesh's normals, else 0.
  double has_uvs;        ///< 1 when `uv` holds the mesh's uvs, else 0.
};

/// A row of hit pixels to resolve: pixel k sees `triangles[triangle[k]]` along the camera ray
/// (ray_x[k], ray_y, 1) in camera space. The per-pixel arrays are read (and the outputs written)
/// up to `count` rounded up to a multiple of resolve_lane_padding().
struct ResolveRow {
  const ResolveTriangle* triangles = nullptr;  ///< The row's triangles.
  const int64_t* triangle = nullptr;           ///< Per pixel: its triangle's index.
  const double* ray_x = nullptr;               ///< Per pixel: camera-space x / z of its ray.
  double ray_y = 0;                            ///< Camera-space y / z of the row's rays.
  double origin[3] = {};                       ///< The camera's world position.
  double rotation[3][3] = {};                  ///< Camera-to-world rotation [row][column].
  size_t count = 0;                            ///< Pixels.
};

/// What the lanes compute per pixel (arrays padded like ResolveRow's).
struct ResolvedHits {
  double* t = nullptr;          ///< Metric z of the hit.
  double* position[3] = {};     ///< World position [axis].
  double* normal[3] = {};       ///< Unit world normal facing the camera [axis].
  double* uv[2] = {};           ///< Interpolated uv [axis] (0 without uvs).
};

/// The lanes of the target resolve_hits_lanes dispatches to: its arrays' padding.
size_t resolve_lane_padding();

/// Re-intersects each pixel's centre ray with its triangle (Moller-Trumbore in double) and writes
/// the hit's z, position, normal and uv: resolve_gbuffer's documented operations, each correctly
/// rounded and in its order (no fused multiply-add), so every target gives the same bits.
void resolve_hits_lanes(const ResolveRow& row, const ResolvedHits& out);

}  // namespace silva::render
