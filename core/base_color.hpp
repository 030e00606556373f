#pragma once
/// @file A surface's own colour from an asset file (texture and/or colour factor), and the
/// 8-bit sRGB <-> linear conversions that carry it through the G-buffer.
#include <cstdint>
#include <vector>

#include "core/types.hpp"

namespace silva {

/// Base colour of a user asset's material: an optional sRGB texture times a linear factor.
/// Texel rows follow AlphaMask: row 0 covers v in [0, 1/height); repeat wrap.
struct BaseColor {
  int width = 0;                   ///< Texels across (0: no texture, the factor alone).
  int height = 0;                  ///< Texels down (0: no texture).
  std::vector<uint8_t> srgb;       ///< width*height*3 sRGB bytes (R, G, B), row-major.
  Vec3f factor = Vec3f::Ones();    ///< Linear RGB multiplier (glTF baseColorFactor, OBJ Kd).
  /// Linear-RGB albedo at (u, v): bilinear between texel centres in linear space, times factor.
  Vec3f albedo(float u, float v) const;
};

/// Linear value of an sRGB-encoded value s in [0, 1] (IEC 61966-2-1 curve, deterministic exp/log).
double srgb_to_linear(double s);

/// Linear value of an 8-bit sRGB code (srgb_to_linear, table lookup).
float srgb8_to_linear(uint8_t code);

/// Linear RGB in [0, 1] (clamped) -> packed sRGB8 R | G << 8 | B << 16 | 0xff << 24 (never 0).
uint32_t pack_srgb8(const Vec3f& linear);

/// Packed sRGB8 colour (pack_srgb8) -> linear RGB.
Vec3f unpack_srgb8(uint32_t packed);

}  // namespace silva
