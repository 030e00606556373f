#pragma once
/// @file Preetham, Shirley & Smits (1999), "A Practical Analytic Model for Daylight", Appendix A:
/// the Perez sky distribution of luminance Y and chromaticity x, y with the paper's turbidity fits,
/// the zenith values, and the sun's colour after Rayleigh and aerosol attenuation. Luminance in
/// kcd/m², illuminance in klx; colours as linear sRGB (D65).
#include "core/types.hpp"

namespace silva::render {

/// The five Perez coefficients A..E of one quantity (Y, x or y).
struct PerezCoefficients {
  double a, b, c, d, e;  ///< Darkening/brightening, gradient, circumsolar strength, width, backscatter.
  /// F(θ, γ) = (1 + A e^(B / cos θ)) (1 + C e^(D γ) + E cos² γ); cos θ <= 0 counts as the horizon.
  double operator()(double cos_theta, double gamma) const;
};

/// The clear sky of one turbidity and sun position (sun at zenith angle θs), in xyY.
struct PreethamSky {
  /// Fits the coefficients and zenith values for turbidity `turbidity` (1.7 .. 10) and the sun
  /// `sun_elevation_rad` above the horizon (clamped to 0 .. π/2: the model has no night).
  PreethamSky(double turbidity, double sun_elevation_rad);

  /// Luminance (kcd/m²) of the sky in direction with zenith cosine `cos_theta`, at angle `gamma` (radians) from the sun.
  double luminance(double cos_theta, double gamma) const;
  /// Linear sRGB radiance (kcd/m² of luminance) in the same direction.
  Vec3d rgb(double cos_theta, double gamma) const;

  double zenith_y;        ///< Zenith luminance Yz, kcd/m².
  double zenith_x;        ///< Zenith chromaticity x.
  double zenith_cy;       ///< Zenith chromaticity y.
  PerezCoefficients y_coeffs, x_coeffs, cy_coeffs;  ///< Perez coefficients of Y, x and y.
  double sun_zenith;      ///< θs, radians.
};

/// xyY -> linear sRGB (D65 primaries), luminance Y unchanged in unit.
Vec3d xyy_to_linear_srgb(double x, double y, double luminance);

/// Fraction of the sun's light reaching the ground per sRGB channel (evaluated at 610, 550 and
/// 465 nm): Rayleigh exp(-0.008735 λ^-4.08 m) times Ångström aerosol exp(-β λ^-1.3 m),
/// β = 0.04608 T - 0.04586, relative air mass m = 1 / (cos θs + 0.15 (93.885 - θs°)^-1.253).
Vec3d sun_transmittance(double turbidity, double sun_elevation_rad);

/// Solar illuminance above the atmosphere, klx.
inline constexpr double kSolarIlluminance = 128.0;

/// Factor on the Preetham sky's luminance that gives its clear sky (turbidity 3) the measured diffuse
/// horizontal illuminance of a clear sky, 0.8 + 15.5 sqrt(sin elevation) klx (the IES clear-sky daylight
/// fit; 14.8 klx at 55 degrees): the model's own sky is about twice that at every elevation from 6 to 70
/// degrees, which leaves the sun only 2.4 times the sky light where real clear days give 5 to 6.
inline constexpr double kPreethamSkyCalibration = 0.48;

}  // namespace silva::render
