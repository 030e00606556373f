#include "render/trail_material.hpp"

#include <algorithm>
#include <cmath>

#include "render/noise_salts.hpp"
#include "core/value_noise.hpp"
#include "core/surface_overlay.hpp"

namespace silva::render {

namespace {

/// Stones: one chance per cell of this edge (metres), centre kept inside its cell.
constexpr float kStoneCell = 0.3f;
/// Roots: one chance per this much arc length (metres).
constexpr float kRootSpacing = 2.2f;

float smoothstep(float e0, float e1, float x) { return smooth_weight(std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f)); }

Vec3f lerp(const Vec3f& a, const Vec3f& b, float t) { return a + (b - a) * t; }

/// Compacted soil: light brown, patchy at the metre scale, grained at the centimetre scale.
Vec3f soil(const Vec3f& p) {
  const float patch = fbm2(p.x() * 0.6f, p.y() * 0.6f, 2, kTrailSoil);
  const float grain = fbm2(p.x() * 7.0f, p.y() * 7.0f, 2, kTrailSoil + 4);
  const float grit = value_noise2(p.x() * 28.0f, p.y() * 28.0f, kTrailSoil + 8);
  const Vec3f dry(0.27f, 0.205f, 0.14f), damp(0.18f, 0.135f, 0.09f);
  return lerp(damp, dry, smoothstep(0.3f, 0.7f, patch)) * ((0.82f + 0.36f * grain) * (0.9f + 0.2f * grit));
}

/// Embedded stone at p, as a weight in [0, 1] and its colour (none: weight 0).
float stone(const Vec3f& p, Vec3f& colour) {
  const float fx = std::floor(p.x() / kStoneCell), fy = std::floor(p.y() / kStoneCell);
  const uint32_t h = lattice_hash(int32_t(fx), int32_t(fy), 0, kTrailStone);
  if (lattice_value(h) > 0.13f) return 0.0f;
  const float cx = (fx + 0.3f + 0.4f * lattice_value(lattice_hash(int32_t(fx), int32_t(fy), 1, kTrailStone))) * kStoneCell;
  const float cy = (fy + 0.3f + 0.4f * lattice_value(lattice_hash(int32_t(fx), int32_t(fy), 2, kTrailStone))) * kStoneCell;
  const float size = lattice_value(lattice_hash(int32_t(fx), int32_t(fy), 3, kTrailStone));
  const float radius = 0.03f + 0.05f * size * size;  // mostly small, a few fist-sized
  const float dx = p.x() - cx, dy = p.y() - cy;
  // A lumpy outline: the radius varies with a noise over the stone's own scale.
  const float k = 1.5f / radius;
  const float lump = 0.75f + 0.5f * value_noise2(dx * k + 7.3f * fx, dy * k + 3.1f * fy, kTrailStone + 5);
  const float r = std::sqrt(dx * dx + dy * dy) / (radius * lump);
  if (r >= 1.0f) return 0.0f;
  const float tone = 0.6f + 0.45f * lattice_value(lattice_hash(int32_t(fx), int32_t(fy), 4, kTrailStone));
  // Warm grey, lighter on top, darker where it meets the soil (it sits in the ground).
  colour = Vec3f(0.22f, 0.19f, 0.15f) * (tone * (1.1f - 0.55f * r * r));
  return smoothstep(1.0f, 0.8f, r);
}

/// Root crossing the trail near arc length s at p (edge coordinate `edge`), as a weight in [0, 1]
/// (0: none) and its shade across its width in `shade` (rounded: lighter along its top).
float root(const Vec3f& p, float s, float edge, float& shade) {
  const float cell = std::floor(s / kRootSpacing);
  const uint32_t h = lattice_hash(int32_t(cell), 0, 0, kTrailRoot);
  if (lattice_value(h) > 0.4f) return 0.0f;
  const float at = (cell + 0.2f + 0.6f * lattice_value(lattice_hash(int32_t(cell), 1, 0, kTrailRoot))) * kRootSpacing;
  const float wander = 0.8f * (fbm2(p.x() * 1.1f, p.y() * 1.1f, 3, kTrailRoot + 2) - 0.5f);
  const float thickness = 0.02f + 0.03f * lattice_value(lattice_hash(int32_t(cell), 2, 0, kTrailRoot));
  const float d = std::abs(s - at - wander) / thickness;
  if (d >= 1.0f) return 0.0f;
  shade = 1.25f - 0.6f * d * d;
  // Half the roots reach in from the edge only and end in the soil (edge coordinate below -reach).
  const float reach = 0.25f + 1.5f * lattice_value(lattice_hash(int32_t(cell), 3, 0, kTrailRoot));
  return smoothstep(1.0f, 0.7f, d) * smoothstep(-reach - 0.15f, -reach, edge);
}

/// Pure trail surface at s (weight 1): soil, litter drifting in near the edge, stones, roots.
Vec3f trail_surface(const SurfacePoint& s, const Vec3f& floor, float edge) {
  const Vec3f& p = s.position;
  Vec3f c = soil(p);
  const float litter = fbm2(p.x() * 2.5f, p.y() * 2.5f, 2, kTrailLitter);
  c = lerp(c, floor, 0.7f * smoothstep(-0.35f, 0.0f, edge + 0.3f * (litter - 0.5f)));
  Vec3f rock;
  const float st = stone(p, rock);
  if (st > 0.0f) c = lerp(c, rock, st);
  float shade = 1.0f;
  const float rt = root(p, s.uv.y(), edge, shade);
  if (rt > 0.0f) c = lerp(c, Vec3f(0.12f, 0.085f, 0.055f) * shade, rt);
  return c;
}

/// Forest floor worn near the trail: trampled, yellow-green grassy fringe fading out by kOverlayMargin.
Vec3f worn_floor(const Vec3f& p, const Vec3f& floor, float edge) {
  const float patches = fbm2(p.x() * 3.0f, p.y() * 3.0f, 2, kTrailFringe);
  const Vec3f grass = Vec3f(0.13f, 0.15f, 0.06f) * (0.8f + 0.4f * patches);
  const float fringe = (1.0f - smoothstep(0.0f, kOverlayMargin, edge)) * smoothstep(0.4f, 0.65f, patches);
  return lerp(floor, grass, 0.65f * fringe);
}

}  // namespace

Vec3f trail_albedo(const SurfacePoint& s) {
  Vec3f floor;
  const float footprint = 0.0f;  // full detail: the floor blended in near the edge
  ground_albedo_row(&s.position, &s.normal, &footprint, 1, &floor, nullptr, nullptr, s.fallen_leaves);
  const float edge = overlay_edge(s.uv.x(), s.position);
  const float w = overlay_weight(edge);
  const Vec3f outside = worn_floor(s.position, floor, edge);
  return w > 0.0f ? lerp(outside, trail_surface(s, floor, edge), w) : outside;
}

}  // namespace silva::render
