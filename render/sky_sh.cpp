#include "render/sky_sh.hpp"

#include <algorithm>
#include <cmath>

namespace silva::render {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr int kNodes = 8;      ///< Gauss–Legendre nodes per hemisphere.
constexpr int kAzimuths = 32;  ///< Even azimuth steps.

/// Gauss–Legendre nodes and weights on [-1, 1] (Newton on the Legendre recurrence).
struct GaussLegendre {
  std::array<double, kNodes> x{}, w{};
  GaussLegendre() {
    for (int i = 0; i < kNodes; ++i) {
      double z = std::cos(kPi * (i + 0.75) / (kNodes + 0.5)), dp = 0.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = z;
        for (int k = 2; k <= kNodes; ++k) {
          const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = kNodes * (z * p1 - p0) / (z * z - 1.0);
        const double step = p1 / dp;
        z -= step;
        if (std::abs(step) < 1e-15) break;
      }
      x[size_t(i)] = z;
      w[size_t(i)] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
  }
};

const GaussLegendre& gauss_legendre() {
  static const GaussLegendre rule;
  return rule;
}

/// The 9 real SH basis functions at unit direction d, order (0,0), (1,-1), (1,0), (1,1), (2,-2) .. (2,2).
std::array<double, 9> basis(const Vec3d& d) {
  const double x = d.x(), y = d.y(), z = d.z();
  return {0.282094791773878, 0.488602511902920 * y, 0.488602511902920 * z, 0.488602511902920 * x,
          1.092548430592079 * x * y, 1.092548430592079 * y * z, 0.315391565252520 * (3.0 * z * z - 1.0),
          1.092548430592079 * x * z, 0.546274215296040 * (x * x - y * y)};
}

/// Calls f(direction, solid-angle weight) for every quadrature sample; `upper_only` skips z < 0.
template <class F>
void for_each_sample(bool upper_only, F&& f) {
  const GaussLegendre& gl = gauss_legendre();
  for (int half = 0; half < (upper_only ? 1 : 2); ++half) {
    for (int i = 0; i < kNodes; ++i) {
      // Map [-1, 1] onto [0, 1] (upper) or [-1, 0] (lower): z = (x + 1) / 2 (- 1), dz = dx / 2.
      const double z = 0.5 * (gl.x[size_t(i)] + 1.0) - (half == 0 ? 0.0 : 1.0);
      const double r = std::sqrt(std::max(1.0 - z * z, 0.0));
      const double weight = 0.5 * gl.w[size_t(i)] * (2.0 * kPi / kAzimuths);
      for (int k = 0; k < kAzimuths; ++k) {
        const double phi = 2.0 * kPi * (k + 0.5) / kAzimuths;
        f(Vec3d(r * std::cos(phi), r * std::sin(phi), z), weight);
      }
    }
  }
}
}  // namespace

Vec3f IrradianceSH::irradiance(const Vec3f& n) const {
  const float x = n.x(), y = n.y(), z = n.z();
  Vec3f e = coeffs[0] + coeffs[1] * y + coeffs[2] * z + coeffs[3] * x + coeffs[4] * (x * y) + coeffs[5] * (y * z) +
            coeffs[6] * (3.0f * z * z - 1.0f) + coeffs[7] * (x * z) + coeffs[8] * (x * x - y * y);
  return e.cwiseMax(0.0f);
}

IrradianceSH fit_irradiance_sh(const std::function<Vec3d(const Vec3d&)>& radiance) {
  std::array<Vec3d, 9> projected;
  projected.fill(Vec3d::Zero());
  for_each_sample(false, [&](const Vec3d& d, double weight) {
    const Vec3d l = radiance(d) * weight;
    const std::array<double, 9> y = basis(d);
    for (size_t k = 0; k < 9; ++k) projected[k] += l * y[k];
  });
  // Cosine convolution per band, then the basis constants folded in so irradiance() is a bare polynomial.
  constexpr double kBand[9] = {kPi, 2.0 * kPi / 3.0, 2.0 * kPi / 3.0, 2.0 * kPi / 3.0, kPi / 4.0, kPi / 4.0,
                               kPi / 4.0, kPi / 4.0, kPi / 4.0};
  constexpr double kBasis[9] = {0.282094791773878, 0.488602511902920, 0.488602511902920, 0.488602511902920,
                                1.092548430592079, 1.092548430592079, 0.315391565252520, 1.092548430592079,
                                0.546274215296040};
  IrradianceSH sh;
  for (size_t k = 0; k < 9; ++k) sh.coeffs[k] = (projected[k] * (kBand[k] * kBasis[k])).cast<float>();
  return sh;
}

Vec3d horizontal_irradiance(const std::function<Vec3d(const Vec3d&)>& radiance) {
  Vec3d e = Vec3d::Zero();
  for_each_sample(true, [&](const Vec3d& d, double weight) { e += radiance(d) * (weight * d.z()); });
  return e;
}

}  // namespace silva::render
