#include <cmath>
#include <numbers>

#include "assets/generators.hpp"
#include "assets/shape_noise.hpp"
#include "assets/wood_parts.hpp"

namespace silva::assets {

namespace {

constexpr int kRings = 12, kAround = 14;

/// Rings of the log's bark surface along X: slight bend, taper, and bark bumps from noise.
std::vector<Vec3f> log_surface(Rng& rng, float length, float r, float axis_z) {
  const ShapeNoise bumps(rng);
  const float bend = rng.range(-0.02f, 0.02f) * length, taper = rng.range(0.8f, 0.95f);
  std::vector<Vec3f> p;
  for (int i = 0; i < kRings; ++i) {
    const float f = float(i) / float(kRings - 1);
    const Vec3f c((f - 0.5f) * length, bend * 4.0f * f * (1.0f - f), axis_z);
    std::vector<float> radii(kAround);
    for (int k = 0; k < kAround; ++k) {
      const float a = 2.0f * std::numbers::pi_v<float> * float(k) / float(kAround);
      const Vec3f q(3.0f * f * length, 2.0f * std::cos(a), 2.0f * std::sin(a));
      radii[size_t(k)] = r * (1.0f + (taper - 1.0f) * f) * (1.0f + 0.07f * bumps.fbm(q, 2));
    }
    const auto ring = ring_points(c, Vec3f::UnitX(), Vec3f::UnitY(), radii);
    p.insert(p.end(), ring.begin(), ring.end());
  }
  return p;
}

/// Short broken-off branch stubs on the upper half of the log.
void add_stubs(MeshBuilder& b, Rng& rng, float length, float r, float axis_z) {
  const int stubs = int(rng.below(4));
  for (int i = 0; i < stubs; ++i) {
    const float x = rng.range(-0.4f, 0.4f) * length, a = rng.range(0.2f, 2.9f);
    const Vec3f dir(rng.range(-0.4f, 0.4f), std::cos(a), std::sin(a));
    const Vec3f base(x, 0.8f * r * dir.y(), axis_z + 0.8f * r * dir.z());
    const float sr = r * rng.range(0.15f, 0.3f), len = r * rng.range(0.4f, 1.2f);
    const TubeNode stub[] = {{base, sr}, {base + len * dir.normalized(), 0.6f * sr}};
    add_tube(b, stub, 6);
  }
}

}  // namespace

GeneratedAsset generate_log(Rng& rng) {
  const float length = rng.range(3.0f, 6.0f);
  const float r = rng.range(0.15f, 0.3f);
  const float axis_z = 0.85f * r;  // resting slightly sunk into the ground
  const std::vector<Vec3f> surface = log_surface(rng, length, r, axis_z);
  MeshBuilder b;
  b.begin_part(Role::Obstacle, Material::LogBark);
  add_ring_grid(b, surface, kRings, kAround);
  add_stubs(b, rng, length, r, axis_z);
  b.begin_part(Role::Obstacle, Material::BrokenWood);
  // The first ring runs clockwise about -X, so reverse it for the cap at the -X end.
  std::vector<Vec3f> start(surface.rbegin() + (kRings - 1) * kAround, surface.rend());
  const std::span<const Vec3f> end(surface.data() + (kRings - 1) * kAround, kAround);
  add_end_cap(b, rng, start, -Vec3f::UnitX(), rng.uniform() < 0.75f ? rng.range(0.3f, 0.9f) : 0.0f);
  add_end_cap(b, rng, end, Vec3f::UnitX(), rng.uniform() < 0.75f ? rng.range(0.3f, 0.9f) : 0.0f);
  CollisionProxy proxy;
  proxy.shape = CollisionProxy::Shape::Capsule;
  proxy.center = Vec3f(0, 0, axis_z);
  proxy.axis = Vec3f::UnitX();
  proxy.radius = 1.1f * r;
  proxy.height = length - 2.0f * r;
  return {b.finish(), Role::Obstacle, proxy};
}

}  // namespace silva::assets
