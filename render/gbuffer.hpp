#pragma once
/// @file The resolved G-buffer: everything a pixel's centre sample saw, for shading and labels.
#include <vector>

#include "core/material.hpp"
#include "core/ontology.hpp"
#include "core/types.hpp"

namespace silva::render {

/// Per-pixel surface data of one view, row-major, width*height entries each.
/// A pixel with depth 0 saw no surface (sky or beyond far): role Background, instance 0.
struct GBuffer {
  int width = 0;                        ///< Pixels across.
  int height = 0;                       ///< Pixels down.
  std::vector<float> depth;             ///< Metric z along the optical axis (metres), 0 = no hit.
  std::vector<Vec3f> position;          ///< World position of the hit.
  std::vector<Vec3f> normal;            ///< Unit world normal, turned to face the camera.
  std::vector<Vec2f> uv;                ///< Interpolated texture coordinates.
  std::vector<Role> role;               ///< Semantic role (class via the ontology).
  std::vector<Material> material;       ///< Procedural material.
  std::vector<uint32_t> instance_id;    ///< Packed instance id, 0 = none.
  std::vector<uint32_t> variation;      ///< Per-instance variation seed (Instance::variation).
  /// Allocates all planes for w x h and clears them to "no hit".
  void resize(int w, int h);
  /// Number of pixels.
  size_t size() const { return size_t(width) * size_t(height); }
};

/// An orthographic sun depth map: light-space depth of the nearest occluder per texel.
struct ShadowMap {
  int width = 0;                  ///< Texels across.
  int height = 0;                 ///< Texels down.
  Mat4d world_to_light = Mat4d::Identity();  ///< World -> light space; light looks along +z.
  double texel_size = 0.0;        ///< Metres per texel (x and y).
  double origin_x = 0, origin_y = 0;  ///< Light-space x, y of texel (0, 0)'s lower corner.
  std::vector<float> depth;       ///< Light-space z of the nearest surface; +inf = nothing.
};

}  // namespace silva::render
