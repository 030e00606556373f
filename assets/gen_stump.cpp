#include <algorithm>
#include <cmath>
#include <numbers>

#include "assets/generators.hpp"
#include "assets/shape_noise.hpp"
#include "assets/wood_parts.hpp"

namespace silva::assets {

namespace {

constexpr int kRings = 7, kAround = 18;

/// Buttress roots around the base: azimuth and strength of each flare lobe.
struct Flares {
  std::vector<float> az, strength;
  /// Extra radius factor at angle a and height fraction f (flares fade by a third of the height).
  float at(float a, float f) const {
    float e = 0;
    for (size_t i = 0; i < az.size(); ++i) {
      const float c = std::max(0.0f, std::cos(a - az[i]));
      e += strength[i] * std::pow(c, 4.0f);
    }
    return e * std::exp(-f / 0.18f);
  }
};

/// Rings of the stump's side from just below the ground to the top (a plane tilted by `tilt`).
std::vector<Vec3f> stump_surface(Rng& rng, const Flares& flares, float height, float r, float tilt) {
  const ShapeNoise bumps(rng);
  std::vector<Vec3f> p;
  for (int i = 0; i < kRings; ++i) {
    const float f = std::pow(float(i) / float(kRings - 1), 1.6f);  // rings crowd near the flared base
    for (int k = 0; k < kAround; ++k) {
      const float a = 2.0f * std::numbers::pi_v<float> * float(k) / float(kAround);
      const float rr = r * (1.0f + 0.25f * std::exp(-f / 0.2f) + flares.at(a, f)) *
                       (1.0f + 0.06f * bumps.fbm(Vec3f(2 * std::cos(a), 2 * std::sin(a), 4 * f), 2));
      const float z = -0.04f + f * (height + 0.04f) + (i + 1 == kRings ? tilt * rr * std::cos(a) : 0.0f);
      p.emplace_back(rr * std::cos(a), rr * std::sin(a), z);
    }
  }
  return p;
}

}  // namespace

GeneratedAsset generate_stump(Rng& rng) {
  constexpr float kPi = std::numbers::pi_v<float>;
  const float height = rng.range(0.3f, 0.9f);
  const float r = rng.range(0.15f, 0.32f);
  Flares flares;
  const int roots = 3 + int(rng.below(4));
  for (int i = 0; i < roots; ++i) {
    flares.az.push_back(2.0f * kPi * (float(i) + rng.range(-0.25f, 0.25f)) / float(roots));
    flares.strength.push_back(rng.range(0.5f, 1.1f));
  }
  const bool broken = rng.uniform() < 0.45f;
  const float tilt = broken ? 0.0f : rng.range(-0.15f, 0.15f);
  const std::vector<Vec3f> surface = stump_surface(rng, flares, height * (broken ? 0.8f : 1.0f), r, tilt);
  MeshBuilder b;
  b.begin_part(Role::Stump, Material::LogBark);
  add_ring_grid(b, surface, kRings, kAround);
  b.begin_part(Role::Stump, Material::BrokenWood);
  const std::span<const Vec3f> top(surface.data() + (kRings - 1) * kAround, kAround);
  const Vec3f up = Vec3f(-tilt, 0, 1).normalized();
  add_end_cap(b, rng, top, up, broken ? 0.2f / r * height * rng.range(0.5f, 1.0f) : 0.0f);
  return {b.finish(), Role::Stump, cylinder_proxy(1.1f * r, height)};
}

}  // namespace silva::assets
