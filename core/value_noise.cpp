#include "core/value_noise.hpp"

namespace silva {

namespace {
/// Integer lattice cell and fraction of one coordinate.
struct Cell {
  int32_t i;  ///< Lattice index (floor).
  float w;    ///< Smooth weight of the fraction.
  float dw;   ///< Derivative of the weight by the coordinate: 6 t (1 - t).
};

Cell cell_of(float x) {
  const float f = std::floor(x), t = x - f;
  return {int32_t(f), smooth_weight(t), 6.0f * t * (1.0f - t)};
}
}  // namespace

float value_noise2(float x, float y, uint32_t salt) {
  const Cell cx = cell_of(x), cy = cell_of(y);
  const float v00 = lattice_value(lattice_hash(cx.i, cy.i, 0, salt));
  const float v10 = lattice_value(lattice_hash(cx.i + 1, cy.i, 0, salt));
  const float v01 = lattice_value(lattice_hash(cx.i, cy.i + 1, 0, salt));
  const float v11 = lattice_value(lattice_hash(cx.i + 1, cy.i + 1, 0, salt));
  return mix(mix(v00, v10, cx.w), mix(v01, v11, cx.w), cy.w);
}

float value_noise3(float x, float y, float z, uint32_t salt) {
  const Cell cx = cell_of(x), cy = cell_of(y), cz = cell_of(z);
  float layer[2];
  for (int k = 0; k < 2; ++k) {
    const float v00 = lattice_value(lattice_hash(cx.i, cy.i, cz.i + k, salt));
    const float v10 = lattice_value(lattice_hash(cx.i + 1, cy.i, cz.i + k, salt));
    const float v01 = lattice_value(lattice_hash(cx.i, cy.i + 1, cz.i + k, salt));
    const float v11 = lattice_value(lattice_hash(cx.i + 1, cy.i + 1, cz.i + k, salt));
    layer[k] = mix(mix(v00, v10, cx.w), mix(v01, v11, cx.w), cy.w);
  }
  return mix(layer[0], layer[1], cz.w);
}

NoiseGradient value_noise3_gradient(float x, float y, float z, uint32_t salt) {
  const Cell cx = cell_of(x), cy = cell_of(y), cz = cell_of(z);
  float layer[2], ddx[2], ddy[2];
  for (int k = 0; k < 2; ++k) {
    const float v00 = lattice_value(lattice_hash(cx.i, cy.i, cz.i + k, salt));
    const float v10 = lattice_value(lattice_hash(cx.i + 1, cy.i, cz.i + k, salt));
    const float v01 = lattice_value(lattice_hash(cx.i, cy.i + 1, cz.i + k, salt));
    const float v11 = lattice_value(lattice_hash(cx.i + 1, cy.i + 1, cz.i + k, salt));
    const float a = mix(v00, v10, cx.w), b = mix(v01, v11, cx.w);
    layer[k] = mix(a, b, cy.w);
    ddx[k] = mix(v10 - v00, v11 - v01, cy.w) * cx.dw;
    ddy[k] = (b - a) * cy.dw;
  }
  return {mix(layer[0], layer[1], cz.w), mix(ddx[0], ddx[1], cz.w), mix(ddy[0], ddy[1], cz.w),
          (layer[1] - layer[0]) * cz.dw};
}

float fbm2(float x, float y, int octaves, uint32_t salt) {
  float sum = 0, amp = 1, norm = 0;
  for (int o = 0; o < octaves; ++o) {
    sum += amp * value_noise2(x, y, salt + uint32_t(o));
    norm += amp;
    amp *= 0.5f;
    x *= 2.0f;
    y *= 2.0f;
  }
  return sum / norm;
}

float fbm3(float x, float y, float z, int octaves, uint32_t salt) {
  float sum = 0, amp = 1, norm = 0;
  for (int o = 0; o < octaves; ++o) {
    sum += amp * value_noise3(x, y, z, salt + uint32_t(o));
    norm += amp;
    amp *= 0.5f;
    x *= 2.0f;
    y *= 2.0f;
    z *= 2.0f;
  }
  return sum / norm;
}

}  // namespace silva
