#include "render/ground_object_materials.hpp"

#include <algorithm>

#include "render/noise_salts.hpp"
#include "core/value_noise.hpp"

namespace silva::render {

namespace {

float step(float e0, float e1, float x) { return smooth_weight(std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f)); }

Vec3f lerp(const Vec3f& a, const Vec3f& b, float t) { return a + (b - a) * t; }

/// Moss cover of an upward-facing point: faces up past `from` (normal z), in noisy patches.
float moss_cover(const SurfacePoint& s, float from, float patchiness, uint32_t salt) {
  const Vec3f& p = s.position;
  const float patch = fbm3(p.x() * 2.5f, p.y() * 2.5f, p.z() * 2.5f, 2, salt);
  return step(from, from + 0.25f, s.normal.z() + 0.4f * (patch - 0.5f)) * step(patchiness, patchiness + 0.2f, patch);
}

/// Moss colour with fine mottling.
Vec3f moss_colour(const Vec3f& p) {
  const float m = value_noise3(p.x() * 40.0f, p.y() * 40.0f, p.z() * 40.0f, kMossMottle);
  return lerp(Vec3f(0.03f, 0.05f, 0.014f), Vec3f(0.06f, 0.085f, 0.022f), m);
}

}  // namespace

Vec3f rock_albedo(const SurfacePoint& s) {
  const Vec3f& p = s.position;
  const float grain = fbm3(p.x() * 3.0f, p.y() * 3.0f, p.z() * 3.0f, 3, kRockGrain);
  const float speckle = value_noise3(p.x() * 60.0f, p.y() * 60.0f, p.z() * 60.0f, kRockGrain + 1);
  const float band = value_noise3(p.x() * 0.8f, p.y() * 0.8f, p.z() * 6.0f, kRockBand);
  Vec3f c = lerp(Vec3f(0.11f, 0.105f, 0.1f), Vec3f(0.16f, 0.15f, 0.135f), band) * (0.7f + 0.5f * grain) *
            (0.85f + 0.3f * speckle);
  const float lichen = step(0.62f, 0.68f, fbm3(p.x() * 6.0f, p.y() * 6.0f, p.z() * 6.0f, 3, kRockLichen));
  const Vec3f lichen_colour = speckle > 0.5f ? Vec3f(0.24f, 0.25f, 0.21f) : Vec3f(0.2f, 0.22f, 0.11f);
  c = lerp(c, lichen_colour, 0.8f * lichen);
  return lerp(c, moss_colour(p), moss_cover(s, 0.6f, 0.42f, kRockMoss));
}

Vec3f log_bark_albedo(const SurfacePoint& s) {
  const Vec3f& p = s.position;
  const float furrow = fbm2(s.uv.x() * 14.0f, s.uv.y() * 1.2f, 3, kLogFurrow);
  const float grain = value_noise3(p.x() * 25.0f, p.y() * 25.0f, p.z() * 25.0f, kLogFurrow + 1);
  Vec3f c = Vec3f(0.13f, 0.095f, 0.07f) * (0.4f + 1.0f * step(0.3f, 0.7f, furrow)) * (0.85f + 0.3f * grain);
  const float weathered = step(0.55f, 0.8f, fbm3(p.x() * 1.5f, p.y() * 1.5f, p.z() * 1.5f, 2, kLogFurrow + 2));
  c = lerp(c, Vec3f(0.19f, 0.18f, 0.16f), 0.5f * weathered);
  return lerp(c, moss_colour(p), moss_cover(s, 0.55f, 0.45f, kLogMoss));
}

Vec3f broken_wood_albedo(const SurfacePoint& s) {
  const Vec3f& p = s.position;
  const float fibre = value_noise3(p.x() * 80.0f, p.y() * 80.0f, p.z() * 8.0f, kBrokenGrain);
  const float rot = step(0.5f, 0.8f, fbm3(p.x() * 6.0f, p.y() * 6.0f, p.z() * 6.0f, 2, kBrokenGrain + 1));
  const Vec3f c = Vec3f(0.27f, 0.21f, 0.14f) * (0.8f + 0.35f * fibre);
  return lerp(c, Vec3f(0.13f, 0.09f, 0.055f), 0.7f * rot);
}

Vec3f moss_albedo(const SurfacePoint& s) {
  const uint32_t h = lattice_hash(int32_t(s.variation), 3, 7, kMossMottle);
  const float tint = lattice_value(h);
  const Vec3f c = moss_colour(s.position);
  return Vec3f(c.x() * (0.85f + 0.5f * tint), c.y() * (0.9f + 0.2f * tint), c.z()) * (0.75f + 0.25f * s.normal.z());
}

Vec3f leaf_litter_albedo(const SurfacePoint& s) {
  const Vec3f& p = s.position;
  const float tone = value_noise3(p.x() * 9.0f, p.y() * 9.0f, p.z() * 9.0f, kLitterTone);
  const float decay = value_noise3(p.x() * 30.0f, p.y() * 30.0f, p.z() * 30.0f, kLitterTone + 1);
  const Vec3f c = lerp(Vec3f(0.085f, 0.045f, 0.02f), Vec3f(0.125f, 0.08f, 0.035f), tone);
  return lerp(c, Vec3f(0.07f, 0.05f, 0.03f), 0.6f * step(0.6f, 0.85f, decay));
}

Vec3f soil_albedo(const SurfacePoint& s) {
  const Vec3f& p = s.position;
  const float mineral = fbm3(p.x() * 4.0f, p.y() * 4.0f, p.z() * 4.0f, 3, kSoilTone);
  const float crumb = value_noise3(p.x() * 45.0f, p.y() * 45.0f, p.z() * 45.0f, kSoilTone + 1);
  const float stone = step(0.86f, 0.9f, value_noise3(p.x() * 14.0f, p.y() * 14.0f, p.z() * 14.0f, kSoilTone + 2));
  const Vec3f c = lerp(Vec3f(0.045f, 0.032f, 0.022f), Vec3f(0.15f, 0.11f, 0.07f), step(0.5f, 0.75f, mineral)) *
                  (0.75f + 0.5f * crumb);
  return lerp(c, Vec3f(0.1f, 0.095f, 0.088f) * (0.8f + 0.4f * crumb), stone);
}

}  // namespace silva::render
