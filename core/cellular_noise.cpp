#include "core/cellular_noise.hpp"

#include <cmath>

#include "core/value_noise.hpp"

namespace silva {

namespace {

/// One step of a 10-bit coordinate.
constexpr float kTenBits = 1.0f / 1024.0f;

/// A feature point's offset from the query point, its squared length and its cell's hash.
struct Feature {
  float dx = 0.0f, dy = 0.0f, dz = 0.0f;
  float d2 = INFINITY;
  uint32_t cell = 0;
};

}  // namespace

CellularSample cellular3(float x, float y, float z, uint32_t salt) {
  const float fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const auto ix = int32_t(fx), iy = int32_t(fy), iz = int32_t(fz);
  Feature first, second;
  for (int k = -1; k <= 1; ++k)
    for (int j = -1; j <= 1; ++j)
      for (int i = -1; i <= 1; ++i) {
        const uint32_t h = lattice_hash(ix + i, iy + j, iz + k, salt);
        // The feature point's three coordinates in the cell: 10 bits of the well-mixed hash each.
        Feature f;
        f.dx = fx + float(i) + float(h & 1023u) * kTenBits - x;
        f.dy = fy + float(j) + float((h >> 10) & 1023u) * kTenBits - y;
        f.dz = fz + float(k) + float((h >> 20) & 1023u) * kTenBits - z;
        f.d2 = f.dx * f.dx + f.dy * f.dy + f.dz * f.dz;
        f.cell = h;
        if (f.d2 < first.d2) {
          second = first;
          first = f;
        } else if (f.d2 < second.d2) {
          second = f;
        }
      }
  CellularSample s;
  s.f1 = std::sqrt(first.d2);
  s.f2 = std::sqrt(second.d2);
  s.nearest_cell = first.cell;
  // d|q - p|/dq = (q - p) / |q - p| with q the query point: minus the offset over its length.
  if (s.f1 > 0.0f && s.f2 > 0.0f) {
    s.gap_dx = first.dx / s.f1 - second.dx / s.f2;
    s.gap_dy = first.dy / s.f1 - second.dy / s.f2;
    s.gap_dz = first.dz / s.f1 - second.dz / s.f2;
  }
  return s;
}

}  // namespace silva
