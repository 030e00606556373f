#include "core/base_color.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/det_math.hpp"

namespace silva {

namespace {

/// Linear values of the 256 sRGB codes.
const std::array<float, 256>& decode_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int c = 0; c < 256; ++c) t[size_t(c)] = float(srgb_to_linear(double(c) / 255.0));
    return t;
  }();
  return table;
}

/// Nearest sRGB code of a linear value: the code whose decoded value is closest (binary search).
uint8_t encode(float linear) {
  const auto& t = decode_table();
  const float x = std::clamp(linear, 0.0f, 1.0f);
  const auto it = std::lower_bound(t.begin(), t.end(), x);
  if (it == t.begin()) return 0;
  if (it == t.end()) return 255;
  const auto below = it - 1;
  return uint8_t((x - *below <= *it - x ? below : it) - t.begin());
}

/// Wraps a texel index into [0, n).
int wrap(int i, int n) {
  const int r = i % n;
  return r < 0 ? r + n : r;
}

}  // namespace

double srgb_to_linear(double s) {
  return s <= 0.04045 ? s / 12.92 : det_exp(2.4 * det_log((s + 0.055) / 1.055));
}

float srgb8_to_linear(uint8_t code) { return decode_table()[code]; }

uint32_t pack_srgb8(const Vec3f& linear) {
  return uint32_t(encode(linear.x())) | uint32_t(encode(linear.y())) << 8 | uint32_t(encode(linear.z())) << 16 |
         0xffu << 24;
}

Vec3f unpack_srgb8(uint32_t packed) {
  return Vec3f(srgb8_to_linear(uint8_t(packed)), srgb8_to_linear(uint8_t(packed >> 8)),
               srgb8_to_linear(uint8_t(packed >> 16)));
}

Vec3f BaseColor::albedo(float u, float v) const {
  if (width <= 0 || height <= 0) return factor;
  // Texel (x, y) has its centre at ((x + 0.5) / width, (y + 0.5) / height).
  const float fx = (u - std::floor(u)) * float(width) - 0.5f;
  const float fy = (v - std::floor(v)) * float(height) - 0.5f;
  const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
  const float wx = fx - float(x0), wy = fy - float(y0);
  auto texel = [&](int x, int y) {
    const size_t i = (size_t(wrap(y, height)) * size_t(width) + size_t(wrap(x, width))) * 3;
    return Vec3f(srgb8_to_linear(srgb[i]), srgb8_to_linear(srgb[i + 1]), srgb8_to_linear(srgb[i + 2]));
  };
  const Vec3f top = (1.0f - wx) * texel(x0, y0) + wx * texel(x0 + 1, y0);
  const Vec3f bottom = (1.0f - wx) * texel(x0, y0 + 1) + wx * texel(x0 + 1, y0 + 1);
  return ((1.0f - wy) * top + wy * bottom).cwiseProduct(factor);
}

}  // namespace silva
