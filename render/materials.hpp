#pragma once
/// @file Procedural, seeded surface colours for every core/material.hpp Material.
#include <cstddef>
#include <cstdint>

#include "core/material.hpp"
#include "core/types.hpp"

namespace silva::render {

/// What a material function needs to know about one visible surface point.
struct SurfacePoint {
  Vec3f position;      ///< World position (metres, Z up).
  Vec3f normal;        ///< Unit world normal facing the camera.
  Vec2f uv;            ///< Mesh texture coordinates (trail: render/trail_material.hpp).
  Material material;   ///< Which procedural material.
  uint32_t variation;  ///< Per-instance variation seed.
};

/// Linear-RGB diffuse albedo of a surface point: a pure function of the point (no state).
Vec3f material_albedo(const SurfacePoint& s);

/// Forest floor (Material::Ground): soil, leaf/needle litter and moss, blended by slope and noise.
/// Colours and the fBm salts of its three noise layers (patches, litter, fine grain):
inline constexpr float kGroundSoil[3] = {0.1f, 0.075f, 0.05f};     ///< Bare soil.
inline constexpr float kGroundLitter[3] = {0.14f, 0.1f, 0.06f};    ///< Leaf/needle litter.
inline constexpr float kGroundMoss[3] = {0.08f, 0.1f, 0.035f};     ///< Moss patches.
inline constexpr uint32_t kGroundPatchSalt = 0x100;   ///< Moss patches, fbm2 of p * 0.15, 3 octaves.
inline constexpr uint32_t kGroundLitterSalt = 0x200;  ///< Litter, fbm2 of p * 0.7, 2 octaves.
inline constexpr uint32_t kGroundFineSalt = 0x300;    ///< Brightness grain, fbm2 of p * 5, 2 octaves.

/// Ground albedo of `count` points (world positions and normals) into out[i], one point per SIMD
/// lane: flat = smoothstep(0.75, 0.95, n.z); c = mix(soil, litter, smoothstep(0.35, 0.6, litter
/// noise) flat); c = mix(c, moss, smoothstep(0.52, 0.68, patch noise) flat); c (0.7 + 0.6 fine),
/// with shading_noise.hpp's fbm2 evaluated lane by lane in its operation order (every target agrees).
void ground_albedo_row(const Vec3f* positions, const Vec3f* normals, size_t count, Vec3f* out);

/// The Highway target ground_albedo_row dispatches to now.
int64_t ground_simd_target();

/// 1 for thin foliage that lets light through when back-lit (needles, leaves, grass, ferns), else 0.
float material_translucency(Material m);

}  // namespace silva::render
