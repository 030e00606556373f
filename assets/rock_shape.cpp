#include "assets/rock_shape.hpp"

#include <algorithm>

#include "assets/generators.hpp"

namespace silva::assets {

float RockShape::radius(const Vec3f& d) const {
  const Vec3f p = frequency * d;
  float r = 1.0f + bulk * noise.fbm(p, 3) + ridges * (2.0f * noise.ridged(2.0f * p, 4) - 1.0f);
  for (const Vec3f& c : cuts) {
    const float offset = c.norm(), along = d.dot(c) / offset;
    if (along > 1e-3f) r = std::min(r, offset / along);
  }
  return std::clamp(r, kRockMinRadius, kRockMaxRadius);
}

RockShape random_rock_shape(Rng& rng) {
  RockShape s{ShapeNoise(rng), rng.range(1.0f, 1.8f), rng.range(0.1f, 0.22f), rng.range(0.05f, 0.12f), {}};
  const int cuts = 2 + int(rng.below(4));
  for (int i = 0; i < cuts; ++i) s.cuts.push_back(rng.range(0.6f, 0.95f) * random_direction(rng));
  return s;
}

}  // namespace silva::assets
