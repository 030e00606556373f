#include "assets/root_plate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "assets/generators.hpp"
#include "assets/shape_noise.hpp"
#include "assets/tree_mesh.hpp"
#include "assets/wood_parts.hpp"

namespace silva::assets {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;
/// Points around each ring of the soil lens.
constexpr int kAround = 20;
/// Rings of the lens from its back (the torn underside) to its front face: x as a share of the
/// plate's depth behind the front face, radius as a share of the outline.
constexpr std::array<float, 5> kRingBack = {1.0f, 0.8f, 0.45f, 0.15f, 0.0f};
constexpr std::array<float, 5> kRingRadius = {0.3f, 0.72f, 0.95f, 1.0f, 0.96f};

/// The plate's outline: radius at angle a (0 = +y, counter-clockwise about +x) as three random
/// lobes on the mean radius, within [kRootPlateMinLobe, kRootPlateMaxLobe] x radius.
struct Outline {
  std::array<float, 3> amplitude{}, phase{};
  explicit Outline(Rng& rng) {
    amplitude = {rng.range(0.06f, 0.14f), rng.range(0.04f, 0.09f), rng.range(0.02f, 0.05f)};
    for (float& p : phase) p = rng.range(0.0f, 2.0f * kPi);
  }
  /// Outline radius over the mean at angle a.
  float lobe(float a) const {
    constexpr std::array<float, 3> kHarmonic = {2.0f, 3.0f, 5.0f};
    float f = 1.0f;
    for (size_t h = 0; h < 3; ++h) f += amplitude[h] * std::cos(kHarmonic[h] * a + phase[h]);
    return f;
  }
};

/// The plate centre: its front face at front_x, its middle raised to 0.55 radius (the lower part
/// stays sunk in the pit it came out of).
Vec3f plate_centre(const RootPlateSize& size) { return {size.front_x, 0.0f, 0.55f * size.radius}; }

/// `p` raised to no lower than 0.2 radius below the ground: the plate's buried part is cut flat, so
/// the asset stays mostly above ground.
Vec3f above_pit(Vec3f p, const RootPlateSize& size) {
  p.z() = std::max(p.z(), -0.2f * size.radius);
  return p;
}

/// Unit vector at angle a in the plate's plane (0 = +y, counter-clockwise about +x).
Vec3f in_plane(float a) { return {0.0f, std::cos(a), std::sin(a)}; }

/// One plate's drawn shape, shared by its parts.
struct Plate {
  RootPlateSize size;  ///< Where and how large.
  Outline outline;     ///< Its lobed outline.
  float depth;         ///< How far its back lies behind its front face (m).
  Vec3f centre;        ///< plate_centre(size).
};

/// Adds the soil lens (rings along +x, lumpy except at the front) and its front face.
void add_soil_lens(MeshBuilder& b, Rng& rng, const Plate& plate) {
  const ShapeNoise lumps(rng);
  const auto& [size, outline, depth, c] = plate;
  std::vector<Vec3f> rings;
  for (size_t r = 0; r < kRingBack.size(); ++r)
    for (int k = 0; k < kAround; ++k) {
      const float a = 2.0f * kPi * float(k) / float(kAround);
      const Vec3f p = c + Vec3f(-kRingBack[r] * depth, 0, 0) + kRingRadius[r] * outline.lobe(a) * size.radius * in_plane(a);
      const float bump = r + 1 < kRingBack.size() ? 0.12f * size.radius * lumps.fbm(2.5f * p / size.radius, 3) : 0.0f;
      rings.push_back(above_pit(p + bump * (p - c).normalized(), size));
    }
  b.begin_part(Role::Obstacle, Material::Soil);
  add_ring_grid(b, rings, int(kRingBack.size()), kAround);
  const std::span<const Vec3f> all(rings);
  std::vector<Vec3f> back(all.begin(), all.begin() + kAround);
  std::reverse(back.begin(), back.end());
  add_end_cap(b, rng, back, -Vec3f::UnitX(), 0.0f);
  b.begin_part(Role::Obstacle, rng.uniform() < 0.5f ? Material::Moss : Material::LeafLitter);
  add_end_cap(b, rng, all.subspan(size_t(kRingBack.size() - 1) * kAround, kAround), Vec3f::UnitX(), 0.0f);
}

/// Thick roots leaving the rim: outward, bending back behind the plate and drooping, broken off
/// 0.35-0.9 of the plate's radius out.
void add_rim_roots(MeshBuilder& b, Rng& rng, const Plate& plate) {
  const auto& [size, outline, depth, c] = plate;
  const int roots = 7 + int(rng.below(6));
  for (int k = 0; k < roots; ++k) {
    const float a = 2.0f * kPi * (float(k) + rng.range(-0.45f, 0.45f)) / float(roots);
    const Vec3f out = in_plane(a), side = Vec3f::UnitX().cross(out);
    const float rim = outline.lobe(a) * size.radius, reach = rim * rng.range(0.35f, 0.9f);
    const float swing = rng.range(-0.5f, 0.5f), back = rng.range(0.1f, 0.6f);
    const Vec3f start = c + Vec3f(-rng.range(0.2f, 0.6f) * depth, 0, 0) + 0.8f * rim * out;
    const float r0 = size.trunk_radius * rng.range(0.18f, 0.38f);
    std::array<TubeNode, 4> nodes;
    const float step = reach / float(nodes.size() - 1);
    Vec3f p = above_pit(start, size);
    for (size_t i = 0; i < nodes.size(); ++i) {
      const float f = float(i) / float(nodes.size() - 1);
      nodes[i] = {p, std::max(kMinTubeRadius, r0 * (1.0f - 0.6f * f))};  // broken off, not tapered to a point
      Vec3f dir = (out + swing * f * side - (back * f + 0.1f) * Vec3f::UnitX() - 0.5f * f * f * Vec3f::UnitZ()).normalized();
      const Vec3f next = p + step * dir;
      if (above_pit(next, size) != next) dir.z() = std::max(dir.z(), 0.0f);  // along the pit's floor
      p += step * dir.normalized();
    }
    add_tube(b, nodes, 6);
  }
}

/// Short torn root ends sticking out of the back of the lens.
void add_torn_ends(MeshBuilder& b, Rng& rng, const Plate& plate) {
  const auto& [size, outline, depth, c] = plate;
  const int ends = 5 + int(rng.below(6));
  for (int k = 0; k < ends; ++k) {
    const float a = rng.range(0.0f, 2.0f * kPi), rho = rng.range(0.1f, 0.8f);
    const Vec3f base = above_pit(
        c + Vec3f(-depth * (1.0f - 0.5f * rho * rho), 0, 0) + rho * outline.lobe(a) * size.radius * in_plane(a), size);
    const Vec3f dir = (-Vec3f::UnitX() + 0.6f * random_direction(rng)).normalized();
    const float r = std::max(kMinTubeRadius * 1.5f, size.trunk_radius * rng.range(0.08f, 0.18f));
    const TubeNode stub[] = {{base + 0.05f * Vec3f::UnitX(), r}, {above_pit(base + rng.range(0.08f, 0.25f) * dir, size), 0.6f * r}};
    add_tube(b, stub, 5);
  }
}

/// Lumps of soil fallen off the plate, lying at its foot.
void add_clods(MeshBuilder& b, Rng& rng, const RootPlateSize& size) {
  const ShapeNoise lumps(rng);
  const Mesh sphere = unit_icosphere(1);
  const int clods = 2 + int(rng.below(4));
  for (int k = 0; k < clods; ++k) {
    const float r = size.radius * rng.range(0.08f, 0.2f);
    const Vec3f at(size.front_x - rng.range(0.2f, 1.0f) * size.radius, rng.range(-0.9f, 0.9f) * size.radius, 0.35f * r);
    std::vector<uint32_t> idx;
    for (const Vec3f& d : sphere.positions) {
      const Vec3f u = d.normalized();
      const float s = r * (1.0f + 0.3f * lumps.fbm(2.0f * u + at, 2));
      idx.push_back(b.vertex(at + Vec3f(s * u.x(), s * u.y(), 0.65f * s * u.z()), u, Vec2f(0.5f + 0.5f * u.x(), 0.5f + 0.5f * u.y())));
    }
    for (size_t t = 0; t < sphere.indices.size(); t += 3)
      b.triangle(idx[sphere.indices[t]], idx[sphere.indices[t + 1]], idx[sphere.indices[t + 2]]);
  }
}

}  // namespace

void add_root_plate(MeshBuilder& b, Rng& rng, const RootPlateSize& size) {
  const Outline outline(rng);
  const Plate plate{size, outline, size.radius * rng.range(0.3f, 0.5f), plate_centre(size)};
  add_soil_lens(b, rng, plate);
  b.begin_part(Role::Obstacle, Material::Soil);
  add_clods(b, rng, size);
  add_torn_ends(b, rng, plate);  // roots caked with soil, as fresh windthrow shows them
  add_rim_roots(b, rng, plate);
}

}  // namespace silva::assets
