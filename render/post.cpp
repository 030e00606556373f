#include "render/post.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

#include "core/base_color.hpp"
#include "core/det_math.hpp"
#include "core/rng.hpp"

namespace silva::render {

namespace {
constexpr int kQuantiles = 65536;

/// Inverse standard normal CDF by Acklam's rational approximation (relative error < 1.2e-9;
/// det_log in the tails so the table is the same on every CPU).
double inverse_normal_cdf(double p) {
  static constexpr double a[] = {-3.969683028665376e+01, 2.209460984245205e+02, -2.759285104469687e+02,
                                 1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
  static constexpr double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                                 6.680131188771972e+01,  -1.328068155288572e+01};
  static constexpr double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                                 -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
  static constexpr double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                                 3.754408661907416e+00};
  constexpr double kLow = 0.02425;
  if (p < kLow || p > 1.0 - kLow) {
    const double q = std::sqrt(-2.0 * det_log(p < kLow ? p : 1.0 - p));
    const double x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
                     ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
    return p < kLow ? x : -x;
  }
  const double q = p - 0.5, r = q * q;
  return (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
         (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
}

/// The 65536 bin-centre quantiles, normalised to mean 0 and variance 1.
const std::array<float, kQuantiles>& quantile_table() {
  static const std::unique_ptr<std::array<float, kQuantiles>> table = [] {
    std::array<double, kQuantiles> q;
    double sum = 0, sum_sq = 0;
    for (int i = 0; i < kQuantiles; ++i) {
      q[size_t(i)] = inverse_normal_cdf((double(i) + 0.5) / double(kQuantiles));
      sum += q[size_t(i)];
    }
    const double mean = sum / kQuantiles;
    for (double v : q) sum_sq += (v - mean) * (v - mean);
    const double scale = 1.0 / std::sqrt(sum_sq / kQuantiles);
    auto t = std::make_unique<std::array<float, kQuantiles>>();
    for (int i = 0; i < kQuantiles; ++i) (*t)[size_t(i)] = float((q[size_t(i)] - mean) * scale);
    return t;
  }();
  return *table;
}

/// 8-bit sRGB code of each of kSrgbTableSize evenly spaced display-linear values in [0, 1]:
/// the number of code boundaries srgb_to_linear((k + 0.5) / 255) at or below the value.
const std::array<uint8_t, kSrgbTableSize>& srgb_table() {
  static const std::array<uint8_t, kSrgbTableSize> table = [] {
    std::array<uint8_t, kSrgbTableSize> t{};
    int code = 0;
    for (int i = 0; i < kSrgbTableSize; ++i) {
      const double x = double(i) / double(kSrgbTableSize - 1);
      while (code < 255 && srgb_to_linear((double(code) + 0.5) / 255.0) <= x) ++code;
      t[size_t(i)] = uint8_t(code);
    }
    return t;
  }();
  return table;
}
}  // namespace

float exposure_scale(float exposure_ev) { return float(det_exp(double(exposure_ev) * 0.693147180559945309417)); }

float tonemap_aces(float x) {
  x = std::max(x, 0.0f);
  const float num = x * (2.51f * x + 0.03f);
  const float den = x * (2.43f * x + 0.59f) + 0.14f;
  return std::min(num / den * kToneGain, 1.0f);
}

uint8_t linear_to_srgb8(float x) {
  const float c = std::clamp(x, 0.0f, 1.0f);
  // c >= 0, so adding 0.5 and truncating rounds half up; these exact bytes are part of the output.
  return srgb_table()[size_t(int(c * float(kSrgbTableSize - 1) + 0.5f))];  // NOLINT(bugprone-incorrect-roundings)
}

const uint8_t* srgb8_table() { return srgb_table().data(); }

float noisy_signal(float x, float normal, const NoiseScale& noise) {
  const float electrons = std::min(std::max(x, 0.0f), 1.0f) * noise.electrons_per_unit;
  return x + normal * (std::sqrt(electrons + noise.read_variance) * noise.unit_per_electron);
}

uint64_t noise_key(std::string_view sequence, uint64_t frame) {
  uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a over the name's bytes
  for (char ch : sequence) {
    h ^= uint8_t(ch);
    h *= 0x100000001b3ULL;
  }
  return hash_combine(h, frame);
}

float normal_quantile(uint16_t index) { return quantile_table()[index]; }

Vec3f sensor_normals(uint64_t seed, uint64_t key, uint64_t pixel) {
  return sensor_normals(RngStreamBits(seed, key, uint64_t(Purpose::SensorNoise)), pixel);
}

Vec3f sensor_normals(const RngStreamBits& stream, uint64_t pixel) {
  const uint64_t bits = stream(pixel);
  const auto& q = quantile_table();
  return Vec3f(q[uint16_t(bits)], q[uint16_t(bits >> 16)], q[uint16_t(bits >> 32)]);
}

}  // namespace silva::render
