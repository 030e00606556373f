#include "assets/wood_parts.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace silva::assets {

void add_ring_grid(MeshBuilder& b, std::span<const Vec3f> p, int rows, int cols) {
  auto at = [&](int r, int c) -> const Vec3f& { return p[size_t(r) * size_t(cols) + size_t((c + cols) % cols)]; };
  std::vector<uint32_t> idx;
  float length = 0;
  for (int r = 0; r < rows; ++r) {
    const int lo = std::max(r - 1, 0), hi = std::min(r + 1, rows - 1);
    if (r > 0) length += (at(r, 0) - at(r - 1, 0)).norm();
    for (int c = 0; c <= cols; ++c) {
      const Vec3f around = at(r, c + 1) - at(r, c - 1), along = at(hi, c) - at(lo, c);
      Vec3f n = around.cross(along);
      if (n.norm() < 1e-9f) n = at(r, c) - 0.5f * (at(r, c) + at(r, c + cols / 2));
      idx.push_back(b.vertex(at(r, c), n, Vec2f(float(c) / float(cols), 0.5f * length)));
    }
  }
  const int w = cols + 1;
  for (int r = 1; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const uint32_t a = idx[size_t(r - 1) * size_t(w) + size_t(c)], bb = idx[size_t(r - 1) * size_t(w) + size_t(c + 1)];
      const uint32_t cc = idx[size_t(r) * size_t(w) + size_t(c + 1)], d = idx[size_t(r) * size_t(w) + size_t(c)];
      b.triangle(a, bb, cc);
      b.triangle(a, cc, d);
    }
}

std::vector<Vec3f> ring_points(const Vec3f& center, const Vec3f& axis, const Vec3f& u, std::span<const float> radii) {
  const Vec3f v = axis.cross(u);
  std::vector<Vec3f> out;
  const size_t n = radii.size();
  for (size_t k = 0; k < n; ++k) {
    const float a = 2.0f * std::numbers::pi_v<float> * float(k) / float(n);
    out.push_back(center + radii[k] * (std::cos(a) * u + std::sin(a) * v));
  }
  return out;
}

void add_end_cap(MeshBuilder& b, Rng& rng, std::span<const Vec3f> ring, const Vec3f& axis, float jag) {
  const size_t n = ring.size();
  Vec3f center = Vec3f::Zero();
  for (const Vec3f& p : ring) center += p;
  center /= float(n);
  float radius = 0;
  for (const Vec3f& p : ring) radius += (p - center).norm() / float(n);
  // Splinter tips (outer) and the broken core (inner) rise along the axis by random amounts.
  std::vector<Vec3f> outer(n), inner(n);
  for (size_t k = 0; k < n; ++k) {
    const Vec3f radial = ring[k] - center;
    const float spike = jag * radius * (k % 2 ? rng.range(0.3f, 1.0f) : rng.range(0.0f, 0.35f));
    outer[k] = center + 0.93f * radial + spike * axis;
    inner[k] = center + 0.45f * radial + (0.5f * spike + jag * radius * rng.range(0.0f, 0.3f)) * axis;
  }
  const Vec3f core = center + jag * radius * rng.range(0.1f, 0.5f) * axis;
  auto band = [&](std::span<const Vec3f> from, std::span<const Vec3f> to, bool radial_normals) {
    std::vector<uint32_t> a(n + 1), c(n + 1);
    for (size_t k = 0; k <= n; ++k) {
      const size_t i = k % n;
      const Vec3f na = radial_normals ? Vec3f((from[i] - center).normalized() + axis) : axis;
      const Vec3f nc = radial_normals ? Vec3f((to[i] - center).normalized() + axis) : axis;
      a[k] = b.vertex(from[i], na, Vec2f(float(k) / float(n), 0));
      c[k] = b.vertex(to[i], nc, Vec2f(float(k) / float(n), 0.1f));
    }
    for (size_t k = 0; k < n; ++k) {
      b.triangle(a[k], a[k + 1], c[k + 1]);
      b.triangle(a[k], c[k + 1], c[k]);
    }
  };
  if (jag > 0) band(ring, outer, true);
  band(jag > 0 ? std::span<const Vec3f>(outer) : ring, inner, false);
  const uint32_t mid = b.vertex(core, axis, Vec2f(0.5f, 0.5f));
  std::vector<uint32_t> in(n);
  for (size_t k = 0; k < n; ++k) in[k] = b.vertex(inner[k], axis, Vec2f(0.5f, 0.5f));
  for (size_t k = 0; k < n; ++k) b.triangle(in[k], in[(k + 1) % n], mid);
}

}  // namespace silva::assets
