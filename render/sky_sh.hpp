#pragma once
/// @file Order-2 spherical harmonics (9 coefficients per channel) of the light arriving from every
/// direction, fitted once per frame, turned into irradiance by the clamped-cosine convolution
/// (Ramamoorthi & Hanrahan 2001: A0 = π, A1 = 2π/3, A2 = π/4) and evaluated per pixel by the normal
/// as a polynomial (no transcendental functions).
#include <array>
#include <functional>

#include "core/types.hpp"

namespace silva::render {

/// Irradiance on a surface of any unit normal, from an order-2 SH fit of the incoming radiance.
struct IrradianceSH {
  std::array<Vec3f, 9> coeffs{};  ///< Irradiance coefficients (convolution included), real SH order (l, m).

  /// Irradiance arriving at a surface of unit normal `n` (never negative).
  Vec3f irradiance(const Vec3f& n) const;
};

/// Projects `radiance(dir)` onto the 9 real SH basis functions by a quadrature exact for
/// polynomials in z of degree <= 15 on each hemisphere (Gauss–Legendre in z over [0, 1] and
/// [-1, 0], 32 even steps in azimuth), so a radiance with a jump at the horizon is fitted as well
/// as a smooth one; then applies the cosine convolution. Deterministic (fixed sample order).
IrradianceSH fit_irradiance_sh(const std::function<Vec3d(const Vec3d&)>& radiance);

/// Cosine-weighted integral of `radiance` over the upper hemisphere (z > 0): the irradiance on a
/// horizontal surface, by the same quadrature as fit_irradiance_sh.
Vec3d horizontal_irradiance(const std::function<Vec3d(const Vec3d&)>& radiance);

}  // namespace silva::render
