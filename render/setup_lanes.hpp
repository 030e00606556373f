#pragma once
/// @file Triangle setup of several triangles at once on Highway SIMD lanes (runtime dispatch), for
/// geometry items inside a perspective view: the same bits as setup_triangle, triangle by triangle.
#include <cstdint>

#include "render/mask_cache.hpp"
#include "render/bin.hpp"
#include "render/triangle_setup.hpp"

namespace silva::render {

/// A run of triangles of one mesh part whose vertices are all projected (SetupVertex::projected)
/// and lie in front of every clip plane of a perspective view, so that no triangle needs clipping;
/// the frustum test is made on the lanes when `frustum_test` is set (the run crosses a frustum plane).
struct LaneTriangles {
  const uint32_t* indices = nullptr;      ///< The mesh's index buffer (3 per triangle).
  uint32_t first = 0;                     ///< First triangle.
  uint32_t count = 0;                     ///< Number of triangles.
  const SetupVertex* vertices = nullptr;  ///< Projected vertices, indexed like the mesh's.
  const Vec2f* uvs = nullptr;             ///< The mesh's uvs (read only when mask is set).
  const AlphaBits* mask = nullptr;        ///< Opacity bits of the part's mask, or null.
  bool cull_back = true;                  ///< Drop triangles that face away.
  uint64_t key_base = 0;                  ///< instance << 32: triangle t's key is key_base | t.
  bool frustum_test = false;              ///< Drop triangles wholly behind one frustum plane.
};

/// Sets up `in`'s triangles on SIMD lanes and bins them into `store`: appends and bins exactly
/// what setup_triangle followed by GeometryStore::bin would, in the same order, and counts them
/// alike (only for a perspective `sv`).
void setup_triangles_lanes(const SetupView& sv, const LaneTriangles& in, const TileGrid& grid, GeometryStore& store);

/// The Highway target setup_triangles_lanes dispatches to now.
int64_t setup_simd_target();

}  // namespace silva::render
