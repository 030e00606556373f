#include "assets/shape_noise.hpp"

#include <cmath>

namespace silva::assets {

namespace {
float smooth(float t) { return t * t * (3.0f - 2.0f * t); }
float lerp(float a, float b, float t) { return a + (b - a) * t; }
}  // namespace

float ShapeNoise::lattice(int x, int y, int z) const {
  uint64_t h = salt_ ^ (uint64_t(uint32_t(x)) * 0x9e3779b97f4a7c15ull) ^ (uint64_t(uint32_t(y)) * 0xc2b2ae3d27d4eb4full) ^
               (uint64_t(uint32_t(z)) * 0x165667b19e3779f9ull);
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdull;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ull;
  h ^= h >> 33;
  return float(h >> 40) * (2.0f / 16777216.0f) - 1.0f;
}

float ShapeNoise::value(const Vec3f& p) const {
  const float fx = std::floor(p.x()), fy = std::floor(p.y()), fz = std::floor(p.z());
  const int x = int(fx), y = int(fy), z = int(fz);
  const float tx = smooth(p.x() - fx), ty = smooth(p.y() - fy), tz = smooth(p.z() - fz);
  float layer[2];
  for (int k = 0; k < 2; ++k) {
    const float a = lerp(lattice(x, y, z + k), lattice(x + 1, y, z + k), tx);
    const float b = lerp(lattice(x, y + 1, z + k), lattice(x + 1, y + 1, z + k), tx);
    layer[k] = lerp(a, b, ty);
  }
  return lerp(layer[0], layer[1], tz);
}

float ShapeNoise::fbm(const Vec3f& p, int octaves) const {
  float sum = 0, amp = 1, norm = 0, freq = 1;
  for (int o = 0; o < octaves; ++o, amp *= 0.5f, freq *= 2.0f) {
    sum += amp * value(freq * p + Vec3f(17.3f * float(o), 5.1f * float(o), 11.7f * float(o)));
    norm += amp;
  }
  return sum / norm;
}

float ShapeNoise::ridged(const Vec3f& p, int octaves) const {
  float sum = 0, amp = 1, norm = 0, freq = 1, weight = 1;
  for (int o = 0; o < octaves; ++o, amp *= 0.5f, freq *= 2.0f) {
    float r = 1.0f - std::abs(value(freq * p + Vec3f(3.7f * float(o), 13.1f * float(o), 7.9f * float(o))));
    r = r * r * weight;
    weight = r;
    sum += amp * r;
    norm += amp;
  }
  return sum / norm;
}

}  // namespace silva::assets
