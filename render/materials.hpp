#pragma once
/// @file Procedural, seeded surface colours for every core/material.hpp Material.
#include <cstdint>

#include "core/material.hpp"
#include "core/types.hpp"

namespace silva::render {

/// What a material function needs to know about one visible surface point.
struct SurfacePoint {
  Vec3f position;      ///< World position (metres, Z up).
  Vec3f normal;        ///< Unit world normal facing the camera.
  Vec2f uv;            ///< Mesh texture coordinates (trail: uv.x across its width, in [0, 1]).
  Material material;   ///< Which procedural material.
  uint32_t variation;  ///< Per-instance variation seed.
};

/// Linear-RGB diffuse albedo of a surface point: a pure function of the point (no state).
Vec3f material_albedo(const SurfacePoint& s);

/// 1 for thin foliage that lets light through when back-lit (needles, leaves, grass, ferns), else 0.
float material_translucency(Material m);

}  // namespace silva::render
