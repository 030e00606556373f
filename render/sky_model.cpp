#include "render/sky_model.hpp"

#include <algorithm>
#include <cmath>

namespace silva::render {

namespace {
constexpr double kPi = 3.14159265358979323846;

/// One coefficient of the paper's linear fits in turbidity: slope T + offset.
double fit(double slope, double offset, double t) { return slope * t + offset; }

/// Zenith chromaticity: [T², T, 1] M [θs³, θs², θs, 1]ᵀ (the paper's cubic fit).
double zenith_chromaticity(const double (&m)[3][4], double t, double ts) {
  const double powers[4] = {ts * ts * ts, ts * ts, ts, 1.0};
  const double rows[3] = {t * t, t, 1.0};
  double out = 0.0;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) out += rows[r] * m[r][c] * powers[c];
  return out;
}

constexpr double kZenithX[3][4] = {{0.00166, -0.00375, 0.00209, 0.0},
                                   {-0.02903, 0.06377, -0.03202, 0.00394},
                                   {0.11693, -0.21196, 0.06052, 0.25886}};
constexpr double kZenithY[3][4] = {{0.00275, -0.00610, 0.00317, 0.0},
                                   {-0.04214, 0.08970, -0.04153, 0.00516},
                                   {0.15346, -0.26756, 0.06670, 0.26688}};
}  // namespace

double PerezCoefficients::operator()(double cos_theta, double gamma) const {
  const double darkening = cos_theta > 1e-6 ? 1.0 + a * std::exp(b / cos_theta) : 1.0;
  const double cg = std::cos(gamma);
  return darkening * (1.0 + c * std::exp(d * gamma) + e * cg * cg);
}

PreethamSky::PreethamSky(double t, double sun_elevation_rad) {
  sun_zenith = kPi / 2 - std::clamp(sun_elevation_rad, 0.0, kPi / 2);
  y_coeffs = {fit(0.1787, -1.4630, t), fit(-0.3554, 0.4275, t), fit(-0.0227, 5.3251, t), fit(0.1206, -2.5771, t),
              fit(-0.0670, 0.3703, t)};
  x_coeffs = {fit(-0.0193, -0.2592, t), fit(-0.0665, 0.0008, t), fit(-0.0004, 0.2125, t), fit(-0.0641, -0.8989, t),
              fit(-0.0033, 0.0452, t)};
  cy_coeffs = {fit(-0.0167, -0.2608, t), fit(-0.0950, 0.0092, t), fit(-0.0079, 0.2102, t), fit(-0.0441, -1.6537, t),
               fit(-0.0109, 0.0529, t)};
  const double chi = (4.0 / 9.0 - t / 120.0) * (kPi - 2.0 * sun_zenith);
  zenith_y = std::max((4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192, 0.0);
  zenith_x = zenith_chromaticity(kZenithX, t, sun_zenith);
  zenith_cy = zenith_chromaticity(kZenithY, t, sun_zenith);
}

double PreethamSky::luminance(double cos_theta, double gamma) const {
  return zenith_y * y_coeffs(cos_theta, gamma) / y_coeffs(1.0, sun_zenith);
}

Vec3d PreethamSky::rgb(double cos_theta, double gamma) const {
  const double x = zenith_x * x_coeffs(cos_theta, gamma) / x_coeffs(1.0, sun_zenith);
  const double y = zenith_cy * cy_coeffs(cos_theta, gamma) / cy_coeffs(1.0, sun_zenith);
  return xyy_to_linear_srgb(x, y, luminance(cos_theta, gamma));
}

Vec3d xyy_to_linear_srgb(double x, double y, double luminance) {
  const double big_x = x / y * luminance, big_z = (1.0 - x - y) / y * luminance;
  return Vec3d(std::max(3.2406 * big_x - 1.5372 * luminance - 0.4986 * big_z, 0.0),
               std::max(-0.9689 * big_x + 1.8758 * luminance + 0.0415 * big_z, 0.0),
               std::max(0.0557 * big_x - 0.2040 * luminance + 1.0570 * big_z, 0.0));
}

Vec3d sun_transmittance(double t, double sun_elevation_rad) {
  const double zenith_deg = 90.0 - std::clamp(sun_elevation_rad, 0.0, kPi / 2) * 180.0 / kPi;
  const double air_mass = 1.0 / (std::cos(zenith_deg * kPi / 180.0) + 0.15 * std::pow(93.885 - zenith_deg, -1.253));
  const double beta = std::max(0.04608 * t - 0.04586, 0.0);
  const double wavelengths_um[3] = {0.610, 0.550, 0.465};
  Vec3d out;
  for (int c = 0; c < 3; ++c) {
    const double l = wavelengths_um[c];
    out[c] = std::exp(-0.008735 * std::pow(l, -4.08) * air_mass) * std::exp(-beta * std::pow(l, -1.3) * air_mass);
  }
  return out;
}

}  // namespace silva::render
