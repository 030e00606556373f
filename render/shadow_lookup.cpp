#include "render/shadow_lookup.hpp"

#include <algorithm>
#include <cmath>

namespace silva::render {

namespace {
constexpr double kMaxSlope = 8.0;        ///< Largest receiver depth gradient used (metres per metre).
constexpr double kConstantBias = 0.02;  ///< Metres, on top of half a texel.
}  // namespace

float shadow_visibility(const ShadowMap& map, const Vec3f& position, const Vec3f& normal, const Vec3f& to_sun) {
  if (map.width <= 0 || map.height <= 0 || map.texel_size <= 0.0) return 1.0f;
  const double texel = map.texel_size;
  const double side = normal.dot(to_sun) < 0.0f ? -1.0 : 1.0;
  const Vec3d n = normal.cast<double>() * side;
  const Vec3d p = position.cast<double>() + n * texel;
  const Eigen::Vector4d l = map.world_to_light * Eigen::Vector4d(p.x(), p.y(), p.z(), 1.0);
  const double fx = (l.x() - map.origin_x) / texel, fy = (l.y() - map.origin_y) / texel;
  if (!(fx >= 0.0 && fy >= 0.0 && fx < double(map.width) && fy < double(map.height))) return 1.0f;
  // Receiver plane in light space: depth changes by (gx, gy) per metre of light x, y.
  const Vec3d nl = map.world_to_light.block<3, 3>(0, 0) * n;
  const double nz = nl.z() < 0.0 ? std::min(nl.z(), -1e-6) : std::max(nl.z(), 1e-6);
  const double gx = std::clamp(-nl.x() / nz, -kMaxSlope, kMaxSlope);
  const double gy = std::clamp(-nl.y() / nz, -kMaxSlope, kMaxSlope);
  const double base = l.z() - (0.5 * texel + kConstantBias);
  // Tent filter: 3x3 bilinear PCF taps = 4x4 texels with weights (1 - a, 1, 1, a) per axis, so the
  // result varies continuously with the position (no texel-sized steps near the camera).
  const double sx = fx - 0.5, sy = fy - 0.5;
  const double fx0 = std::floor(sx), fy0 = std::floor(sy);
  const float ax = float(sx - fx0), ay = float(sy - fy0);
  const float wx[4] = {1.0f - ax, 1.0f, 1.0f, ax}, wy[4] = {1.0f - ay, 1.0f, 1.0f, ay};
  const int tx = int(fx0) - 1, ty = int(fy0) - 1;
  // Per column and row: texel index and receiver-depth offset (gx * ox, gy * oy), so each tap is
  // (base + column offset) + row offset, the same sum as evaluating the plane per tap.
  size_t column[4];
  double column_offset[4];
  for (int i = 0; i < 4; ++i) {
    const int x = std::clamp(tx + i, 0, map.width - 1);
    column[i] = size_t(x);
    column_offset[i] = base + gx * ((double(x) + 0.5 - fx) * texel);
  }
  float lit = 0.0f, dark = 0.0f;
  for (int j = 0; j < 4; ++j) {
    const int y = std::clamp(ty + j, 0, map.height - 1);
    const double row_offset = gy * ((double(y) + 0.5 - fy) * texel);
    const float* row = map.depth.data() + size_t(y) * size_t(map.width);
    float row_lit = 0.0f, row_dark = 0.0f;
    for (int i = 0; i < 4; ++i) {
      const double receiver = column_offset[i] + row_offset;
      (float(receiver) <= row[column[i]] ? row_lit : row_dark) += wx[i];
    }
    lit += row_lit * wy[j];
    dark += row_dark * wy[j];
  }
  return lit / (lit + dark);  // exactly 1 when no tap is shadowed, 0 when every weighted tap is
}

}  // namespace silva::render
