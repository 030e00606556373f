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
  std::vector<uint32_t> base_color;     ///< Own albedo of textured asset parts (pack_srgb8); 0 = use `material`.
  std::vector<uint32_t> instance_id;    ///< Packed instance id, 0 = none.
  std::vector<uint32_t> variation;      ///< Per-instance variation seed (Instance::variation).
  std::vector<uint8_t> leaf;            ///< Mask alpha the pixel saw, from the leaf mips at its footprint (0: no mask; leaf_brightness).
  std::vector<float> mask_texels;       ///< Alpha-mask texels across the pixel's footprint (0: no mask): > 1 is minified.
  /// Allocates all planes for w x h and clears them to "no hit".
  void resize(int w, int h);
  /// Number of pixels.
  size_t size() const { return size_t(width) * size_t(height); }
};

/// An orthographic sun depth map: light-space depth of the nearest occluder per texel.
///
/// Convention (render/shadow_pass.hpp builds it, render::Renderer fills it):
///   - Light space is right-handed and metric: p_light = world_to_light * p_world, a pure
///     rotation (no translation, no scale). Its +z axis points AWAY from the sun (the direction
///     sunlight travels), so larger z is farther from the sun; x = normalize(h x z) and
///     y = z x x, with h = world +Z (world +X when the sun is within ~8 degrees of the zenith
///     or nadir).
///   - Texel (x, y) (x < width, y < height) covers light-space x in
///     [origin_x + x*texel_size, origin_x + (x+1)*texel_size) and y in
///     [origin_y + y*texel_size, origin_y + (y+1)*texel_size); its sample is the centre.
///     depth[y*width + x] is that texel. The texels cover the light-space footprint of the
///     region the map was built for (square texels; width and height may differ).
///   - depth = light-space z of the nearest surface (any facing) along +z through the texel
///     centre; +inf where no surface is hit. A world point p is lit when
///     (world_to_light * p).z <= depth at its texel (plus a bias of the shader's choice).
struct ShadowMap {
  int width = 0;                  ///< Texels across.
  int height = 0;                 ///< Texels down.
  Mat4d world_to_light = Mat4d::Identity();  ///< World -> light space; light looks along +z.
  double texel_size = 0.0;        ///< Metres per texel (x and y).
  double origin_x = 0, origin_y = 0;  ///< Light-space x, y of texel (0, 0)'s lower corner.
  std::vector<float> depth;       ///< Light-space z of the nearest surface; +inf = nothing.
};

}  // namespace silva::render
