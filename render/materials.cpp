#include "render/materials.hpp"

#include <algorithm>
#include <cmath>

#include "render/ground_object_materials.hpp"
#include "render/bark_materials.hpp"
#include "core/value_noise.hpp"
#include "render/trail_material.hpp"

namespace silva::render {

namespace {

float smoothstep(float e0, float e1, float x) {
  const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return smooth_weight(t);
}

Vec3f lerp(const Vec3f& a, const Vec3f& b, float t) { return a + (b - a) * t; }

/// Per-instance tint: brightness and a green/yellow shift from the variation seed.
Vec3f variation_tint(uint32_t variation) {
  const uint32_t h = lattice_hash(int32_t(variation), 17, 3, kFoliage);
  const float bright = 0.8f + 0.4f * lattice_value(h);
  const float yellow = 0.25f * lattice_value(lattice_hash(int32_t(variation), 5, 11, kFoliage));
  return Vec3f(bright * (1.0f + yellow), bright * (1.0f + 0.4f * yellow), bright * (1.0f - 0.5f * yellow));
}

/// Forest floor (ground_albedo_row for one point, at full detail: zero footprint).
Vec3f ground(const SurfacePoint& s) {
  Vec3f c;
  const float footprint = 0.0f;
  ground_albedo_row(&s.position, &s.normal, &footprint, 1, &c, nullptr, nullptr, s.floor);
  return c;
}

/// Bark: base colour with vertical streaks (noise stretched along world z) and optional lichen.
Vec3f bark(const SurfacePoint& s, const Vec3f& base, float streak_depth, float lichen) {
  const Vec3f& p = s.position;
  const float streak = fbm3(p.x() * 9.0f, p.y() * 9.0f, p.z() * 0.7f, 3, kBarkStreak);
  const float grain = value_noise3(p.x() * 30.0f, p.y() * 30.0f, p.z() * 4.0f, kBarkStreak + 7);
  Vec3f c = base * (1.0f - streak_depth + 2.0f * streak_depth * streak) * (0.85f + 0.3f * grain);
  if (lichen > 0.0f) {
    const float l = smoothstep(0.6f, 0.75f, fbm3(p.x() * 2.0f, p.y() * 2.0f, p.z() * 2.0f, 2, kBarkLichen));
    c = lerp(c, Vec3f(0.22f, 0.26f, 0.16f), l * lichen);
  }
  return c;
}

/// Foliage: base green, per-instance tint, small per-point mottling.
Vec3f foliage(const SurfacePoint& s, const Vec3f& base) {
  const Vec3f& p = s.position;
  const float scale = kFoliageMottleScale;
  return foliage_albedo(base, s.variation, value_noise3(p.x() * scale, p.y() * scale, p.z() * scale, kFoliageMottleSalt),
                        s.leaf_shade);
}

/// White tepals (wood anemone): the mask's brightness and a little mottle, a faint pink on some plants.
Vec3f petals(const SurfacePoint& s) {
  const Vec3f& p = s.position;
  const float scale = kFoliageMottleScale;
  const float mottle = value_noise3(p.x() * scale, p.y() * scale, p.z() * scale, kFoliageMottleSalt);
  const float pink = 0.06f * lattice_value(lattice_hash(int32_t(s.variation), 7, 13, kFoliage));
  return Vec3f(0.6f, 0.58f - pink, 0.56f - 0.5f * pink) * (0.92f + 0.12f * mottle) * s.leaf_shade;
}

/// Grass: `fresh` with `dry` patches across the ground, lighter towards the blade tip (v = 0).
Vec3f grass(const SurfacePoint& s, const Vec3f& fresh, const Vec3f& dry) {
  const Vec3f& p = s.position;
  const float patch = smoothstep(0.5f, 0.75f, fbm2(p.x() * 0.3f, p.y() * 0.3f, 2, kFoliage + 2));
  const float tip = 1.0f - std::clamp(s.uv.y(), 0.0f, 1.0f);
  return foliage(s, lerp(fresh, dry, patch)) * (0.75f + 0.4f * tip);
}

/// Autumn leaves: each tree turned its own way (its variation) from yellow-green through yellow
/// and orange to brown, patches of the crown ahead or behind.
Vec3f autumn_leaves(const SurfacePoint& s) {
  const Vec3f& p = s.position;
  const float tree = float(s.variation >> 16) / 65535.0f;
  const float patch = fbm2(p.x() * 0.7f + 0.4f * p.z(), p.y() * 0.7f - 0.4f * p.z(), 2, kAutumnTurn);
  const float turn = std::clamp(0.15f + 0.7f * tree + 0.6f * (patch - 0.5f), 0.0f, 1.0f);
  const Vec3f green(0.16f, 0.19f, 0.04f), yellow(0.4f, 0.29f, 0.03f), orange(0.38f, 0.13f, 0.02f),
      brown(0.19f, 0.095f, 0.035f);
  const Vec3f base = turn < 0.35f   ? lerp(green, yellow, turn / 0.35f)
                     : turn < 0.7f  ? lerp(yellow, orange, (turn - 0.35f) / 0.35f)
                                    : lerp(orange, brown, (turn - 0.7f) / 0.3f);
  return foliage(s, base);
}

/// Wood of logs and stumps: weathered bark-brown sides, pale cut faces on top with rings.
Vec3f wood(const SurfacePoint& s) {
  const Vec3f& p = s.position;
  const Vec3f side = bark(s, Vec3f(0.2f, 0.14f, 0.09f), 0.3f, 0.5f);
  const float rings = value_noise2(p.x() * 20.0f, p.y() * 20.0f, kWood);
  const Vec3f cut = Vec3f(0.42f, 0.31f, 0.19f) * (0.85f + 0.3f * rings);
  return lerp(side, cut, smoothstep(0.85f, 0.95f, s.normal.z()));
}

/// The value noise whose gradient bumps a material's shading normal: frequencies per world axis
/// (1/m), salt, and relief height per unit of noise (metres; 0 = smooth).
struct Relief {
  float fx, fy, fz;
  uint32_t salt;
  float height;
};

/// Each material's relief: the grain noise of its albedo function.
Relief relief(Material m) {
  switch (m) {
    case Material::BarkConifer:
    case Material::BarkBroadleaf:
    case Material::BarkDead: return {30.0f, 30.0f, 4.0f, kBarkStreak + 7, 0.008f};  // bark()'s grain
    case Material::Wood: return {30.0f, 30.0f, 4.0f, kBarkStreak + 7, 0.005f};
    case Material::BarkSpruce: return {40.0f, 40.0f, 12.0f, kBarkPlate, 0.005f};     // furrowed()'s grain
    case Material::BarkPine:
    case Material::BarkLarch:
    case Material::BarkOak: return {40.0f, 40.0f, 12.0f, kBarkPlate, 0.009f};
    case Material::BarkBeech:
    case Material::BarkBirch: return {40.0f, 40.0f, 12.0f, kBarkPlate, 0.0025f};
    case Material::LogBark: return {25.0f, 25.0f, 25.0f, kLogFurrow + 1, 0.006f};
    case Material::BrokenWood: return {80.0f, 80.0f, 8.0f, kBrokenGrain, 0.0015f};
    case Material::Rock: return {3.0f, 3.0f, 3.0f, kRockGrain, 0.06f};  // the grain fBm's first octave
    case Material::Soil: return {45.0f, 45.0f, 45.0f, kSoilTone + 1, 0.004f};  // soil_albedo()'s crumbs
    default: return {1.0f, 1.0f, 1.0f, 0, 0.0f};
  }
}

}  // namespace

bool plain_foliage_base(Material m, Vec3f& base) {
  switch (m) {
    case Material::Needles: base = Vec3f(0.045f, 0.1f, 0.035f); return true;
    case Material::Leaves: base = Vec3f(0.08f, 0.17f, 0.035f); return true;
    case Material::Fern: base = Vec3f(0.07f, 0.18f, 0.04f); return true;
    case Material::ShrubLeaves: base = Vec3f(0.07f, 0.14f, 0.045f); return true;
    case Material::NeedlesSpruce: base = Vec3f(0.025f, 0.06f, 0.03f); return true;
    case Material::NeedlesPine: base = Vec3f(0.06f, 0.1f, 0.05f); return true;
    case Material::NeedlesLarch: base = Vec3f(0.11f, 0.2f, 0.05f); return true;
    case Material::LeavesBeech: base = Vec3f(0.08f, 0.18f, 0.035f); return true;
    case Material::LeavesBirch: base = Vec3f(0.13f, 0.22f, 0.045f); return true;
    case Material::LeavesOak: base = Vec3f(0.06f, 0.14f, 0.03f); return true;
    case Material::AutumnNeedles: base = Vec3f(0.36f, 0.25f, 0.045f); return true;
    case Material::BareTwigs: base = Vec3f(0.11f, 0.095f, 0.08f); return true;
    case Material::DeadBracken: base = Vec3f(0.15f, 0.115f, 0.085f); return true;
    case Material::MattedBracken: base = Vec3f(0.12f, 0.06f, 0.03f); return true;
    case Material::Herb: base = Vec3f(0.085f, 0.2f, 0.05f); return true;
    case Material::SpringLeaves: base = Vec3f(0.15f, 0.27f, 0.05f); return true;
    default: return false;
  }
}

Vec3f foliage_albedo(const Vec3f& base, uint32_t variation, float mottle, float leaf_shade) {
  return base.cwiseProduct(variation_tint(variation)) * (0.8f + 0.4f * mottle) * leaf_shade;
}

Vec3f material_albedo(const SurfacePoint& s) {
  Vec3f foliage_base;
  if (plain_foliage_base(s.material, foliage_base)) return foliage(s, foliage_base);
  switch (s.material) {
    case Material::Ground: return ground(s);
    case Material::Trail: return trail_albedo(s);
    case Material::BarkConifer: return bark(s, Vec3f(0.15f, 0.085f, 0.055f), 0.45f, 0.0f);
    case Material::BarkBroadleaf: return bark(s, Vec3f(0.2f, 0.18f, 0.15f), 0.25f, 0.6f);
    case Material::BarkDead: return bark(s, Vec3f(0.24f, 0.22f, 0.195f), 0.6f, 0.0f);  // weathered silver-grey wood
    case Material::Grass: return grass(s, Vec3f(0.1f, 0.19f, 0.04f), Vec3f(0.24f, 0.22f, 0.08f));
    case Material::Rock: return rock_albedo(s);
    case Material::Wood: return wood(s);
    case Material::LogBark: return log_bark_albedo(s);
    case Material::BrokenWood: return broken_wood_albedo(s);
    case Material::Moss: return moss_albedo(s);
    case Material::LeafLitter: return leaf_litter_albedo(s);
    case Material::Soil: return soil_albedo(s);
    case Material::BarkSpruce:
    case Material::BarkPine:
    case Material::BarkLarch:
    case Material::BarkBeech:
    case Material::BarkBirch:
    case Material::BarkOak: return species_bark(s).albedo;
    case Material::AutumnLeaves: return autumn_leaves(s);
    case Material::Petals: return petals(s);
    case Material::AutumnGrass: return grass(s, Vec3f(0.19f, 0.17f, 0.06f), Vec3f(0.3f, 0.22f, 0.09f));
    case Material::WinterGrass: return grass(s, Vec3f(0.27f, 0.24f, 0.16f), Vec3f(0.2f, 0.16f, 0.11f));
    case Material::Needles:
    case Material::Leaves:
    case Material::Fern:
    case Material::ShrubLeaves:
    case Material::NeedlesSpruce:
    case Material::NeedlesPine:
    case Material::NeedlesLarch:
    case Material::LeavesBeech:
    case Material::LeavesBirch:
    case Material::LeavesOak:
    case Material::AutumnNeedles:
    case Material::BareTwigs:
    case Material::DeadBracken:
    case Material::Herb:
    case Material::SpringLeaves:
    case Material::MattedBracken:  // plain foliage, returned above
    case Material::Count: break;
  }
  return Vec3f(0.5f, 0.0f, 0.5f);
}

Vec3f bumped_normal(const Vec3f& n, const Vec3f& slope) {
  const Vec3f tilted = n - (slope - n * n.dot(slope));
  return tilted * (1.0f / std::sqrt(tilted.dot(tilted)));
}

Vec3f material_shading_normal(const SurfacePoint& s, float footprint, const Vec3f& relief_slope) {
  const Relief r = relief(s.material);
  if (r.height <= 0.0f) return s.normal;
  const float fade = 1.0f - smoothstep(0.15f, 0.4f, footprint * std::max({r.fx, r.fy, r.fz}));
  Vec3f slope = Vec3f::Zero();
  if (fade > 0.0f) {
    const Vec3f& p = s.position;
    const NoiseGradient g = value_noise3_gradient(p.x() * r.fx, p.y() * r.fy, p.z() * r.fz, r.salt);
    const float h = r.height * fade;
    slope = Vec3f(g.dx * r.fx * h, g.dy * r.fy * h, g.dz * r.fz * h);
  }
  if (relief_slope != Vec3f::Zero()) slope += relief_slope;
  else if (fade <= 0.0f) return s.normal;
  return bumped_normal(s.normal, slope);
}

float fallen_leaf_cover(Season season) { return season == Season::Autumn ? 0.8f : 0.0f; }

}  // namespace silva::render
