#include "render/bark_materials.hpp"

#include <algorithm>
#include <cmath>

#include "render/noise_salts.hpp"
#include "core/value_noise.hpp"

namespace silva::render {

namespace {

float smoothstep(float e0, float e1, float x) { return smooth_weight(std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f)); }

Vec3f lerp(const Vec3f& a, const Vec3f& b, float t) { return a + (b - a) * t; }

/// Depth of vertical furrows in [0, 1] (1 = deep in a furrow): ridged noise stretched along z.
float furrows(const Vec3f& p, float across, float along) {
  const float n = fbm3(p.x() * across, p.y() * across, p.z() * along, 3, kBarkFurrow);
  return 1.0f - smoothstep(0.0f, 0.35f, std::abs(n - 0.5f) * 2.0f);
}

/// Furrowed bark: ridges of `ridge` colour, furrows `depth` darker, fine grain.
Vec3f furrowed(const Vec3f& p, const Vec3f& ridge, float depth, float across, float along) {
  const float grain = value_noise3(p.x() * 40.0f, p.y() * 40.0f, p.z() * 12.0f, kBarkPlate);
  return ridge * (1.0f - depth * furrows(p, across, along)) * (0.85f + 0.3f * grain);
}

/// Scots pine: grey-brown furrowed plates low, thin orange flakes from about 40 % of the height.
Vec3f pine(const SurfacePoint& s) {
  const Vec3f& p = s.position;
  const Vec3f low = furrowed(p, Vec3f(0.2f, 0.15f, 0.11f), 0.7f, 7.0f, 0.9f);
  const float flake = value_noise3(p.x() * 18.0f, p.y() * 18.0f, p.z() * 6.0f, kBarkPlate + 1);
  const Vec3f high = Vec3f(0.46f, 0.2f, 0.07f) * (0.75f + 0.35f * flake);
  const float wobble = 0.12f * (fbm3(p.x() * 1.5f, p.y() * 1.5f, p.z() * 0.5f, 2, kBarkBlotch) - 0.5f);
  return lerp(low, high, smoothstep(0.3f, 0.5f, s.uv.y() + wobble));
}

/// Silver birch: white with dark horizontal lenticels and black patches, dark fissured base.
Vec3f birch(const SurfacePoint& s) {
  const Vec3f& p = s.position;
  Vec3f c = Vec3f(0.55f, 0.54f, 0.5f) * (0.9f + 0.1f * value_noise3(p.x() * 8.0f, p.y() * 8.0f, p.z() * 8.0f, kBarkPlate));
  const float dash = value_noise3(p.x() * 5.0f, p.y() * 5.0f, p.z() * 45.0f, kBarkMark);
  c = lerp(c, Vec3f(0.06f, 0.055f, 0.05f), smoothstep(0.78f, 0.84f, dash));
  const float patch = fbm3(p.x() * 2.5f, p.y() * 2.5f, p.z() * 1.2f, 3, kBarkBlotch);
  c = lerp(c, Vec3f(0.05f, 0.045f, 0.04f), smoothstep(0.68f, 0.74f, patch));
  const Vec3f base = furrowed(p, Vec3f(0.16f, 0.14f, 0.12f), 0.75f, 9.0f, 1.2f);
  const float wobble = 0.06f * (fbm3(p.x() * 2.0f, p.y() * 2.0f, p.z() * 0.6f, 2, kBarkBlotch + 1) - 0.5f);
  return lerp(base, c, smoothstep(0.06f, 0.14f, s.uv.y() + wobble));
}

/// Beech: smooth pale grey with soft darker and greenish blotches, paler lichen patches, fine dark
/// horizontal wrinkles, and a darker mossy foot.
Vec3f beech(const SurfacePoint& s) {
  const Vec3f& p = s.position;
  const float blotch = fbm3(p.x() * 3.0f, p.y() * 3.0f, p.z() * 1.5f, 3, kBarkBlotch);
  Vec3f c = Vec3f(0.36f, 0.36f, 0.33f) * (0.8f + 0.35f * blotch);
  c = lerp(c, Vec3f(0.2f, 0.24f, 0.15f), 0.5f * smoothstep(0.62f, 0.8f, blotch));
  const float lichen = fbm3(p.x() * 6.0f, p.y() * 6.0f, p.z() * 4.0f, 2, kBarkMark + 1);
  c = lerp(c, Vec3f(0.5f, 0.5f, 0.46f), 0.7f * smoothstep(0.64f, 0.72f, lichen));
  const float wrinkle = value_noise3(p.x() * 5.0f, p.y() * 5.0f, p.z() * 60.0f, kBarkMark + 2);
  c *= 1.0f - 0.3f * smoothstep(0.82f, 0.88f, wrinkle);
  const float wobble = 0.01f * (fbm3(p.x() * 2.0f, p.y() * 2.0f, p.z() * 0.6f, 2, kBarkBlotch + 1) - 0.5f);
  return lerp(c, Vec3f(0.12f, 0.13f, 0.08f), 0.8f * (1.0f - smoothstep(0.01f, 0.035f, s.uv.y() + wobble)));
}

}  // namespace

Vec3f species_bark_albedo(const SurfacePoint& s) {
  const Vec3f& p = s.position;
  switch (s.material) {
    case Material::BarkSpruce: return furrowed(p, Vec3f(0.2f, 0.11f, 0.075f), 0.35f, 22.0f, 8.0f);
    case Material::BarkPine: return pine(s);
    case Material::BarkLarch: return furrowed(p, Vec3f(0.25f, 0.12f, 0.08f), 0.6f, 8.0f, 1.0f);
    case Material::BarkBeech: return beech(s);
    case Material::BarkBirch: return birch(s);
    case Material::BarkOak: return furrowed(p, Vec3f(0.2f, 0.18f, 0.15f), 0.75f, 8.0f, 1.0f);
    default: return Vec3f(0.5f, 0.0f, 0.5f);
  }
}

}  // namespace silva::render
