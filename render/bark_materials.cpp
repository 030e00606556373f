#include "render/bark_materials.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/cellular_noise.hpp"
#include "core/value_noise.hpp"
#include "render/noise_salts.hpp"

namespace silva::render {

namespace {

float smoothstep(float e0, float e1, float x) { return smooth_weight(std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f)); }

Vec3f lerp(const Vec3f& a, const Vec3f& b, float t) { return a + (b - a) * t; }

/// A plated bark: cells of cellular noise stretched along the trunk, separated by fissures of one
/// width in metres whatever their direction.
struct Plated {
  float r, g, b;        ///< Plate colour (linear albedo).
  float fr, fg, fb;     ///< Colour on a fissure's floor (linear albedo).
  float across, along;  ///< Plates per metre across the trunk and along world z.
  float width;          ///< Fissure width (m) from its floor to the plate's edge.
  float relief;         ///< Fissure depth (m).
  float tone;           ///< Plate-to-plate brightness variation (share).
  float mean_fissure;   ///< The fissure depth's average over a trunk (measured): what a pixel spanning many plates sees.
};

constexpr Plated kSpruceScales{0.2f, 0.11f, 0.075f, 0.09f, 0.045f, 0.03f, 14.0f, 8.0f, 0.006f, 0.005f, 0.3f, 0.16f};
constexpr Plated kPinePlates{0.17f, 0.135f, 0.1f, 0.05f, 0.03f, 0.02f, 9.0f, 2.0f, 0.02f, 0.03f, 0.3f, 0.37f};
constexpr Plated kLarchPlates{0.27f, 0.15f, 0.1f, 0.12f, 0.04f, 0.025f, 7.0f, 2.2f, 0.018f, 0.02f, 0.25f, 0.27f};
constexpr Plated kOakRidges{0.16f, 0.15f, 0.13f, 0.05f, 0.045f, 0.04f, 6.0f, 0.8f, 0.02f, 0.03f, 0.2f, 0.23f};
constexpr Plated kBirchBase{0.18f, 0.16f, 0.14f, 0.04f, 0.035f, 0.03f, 8.0f, 1.8f, 0.015f, 0.015f, 0.2f, 0.26f};

/// Where the plate pattern is drawn in detail: 1 while a pixel spans less than half a fissure's
/// width, 0 from two widths (there the bark shows its average).
float plate_detail(const Plated& b, float footprint) { return 1.0f - smoothstep(0.5f * b.width, 2.0f * b.width, footprint); }

/// A point's plate: its distance from the nearest fissure's floor, that distance's gradient and the
/// plate's id.
struct PlateSample {
  float metres;          ///< Distance from the nearest fissure's floor (m) over that fissure's own opening.
  Vec3f towards_plate;   ///< Unit gradient of `metres` (world axes).
  uint32_t plate;        ///< Id of the plate (its cell's hash).
  /// Fissure depth in [0, 1]: 1 on the floor, 0 from `width` away.
  float fissure(float width) const { return 1.0f - smoothstep(0.0f, width, metres); }
};

/// The plate at p: the gap between the nearest two cells' distances, turned into metres by its own
/// gradient, so fissures keep their width across and along the trunk. The cells are warped by value
/// noise so plate edges wander instead of running straight.
PlateSample plate_at(const Vec3f& p, const Plated& b) {
  const float f = 0.7f * b.across, warp = 0.35f;
  const float x = p.x() * b.across + warp * (value_noise3(p.x() * f, p.y() * f, p.z() * f, kBarkFurrow + 1) - 0.5f);
  const float y = p.y() * b.across + warp * (value_noise3(p.x() * f, p.y() * f, p.z() * f, kBarkFurrow + 2) - 0.5f);
  const float z = p.z() * b.along + warp * (value_noise3(p.x() * f, p.y() * f, p.z() * f, kBarkFurrow + 3) - 0.5f);
  const CellularSample c = cellular3(x, y, z, kBarkFurrow);
  const Vec3f gradient(c.gap_dx * b.across, c.gap_dy * b.across, c.gap_dz * b.along);
  const float steepness = gradient.norm();
  if (steepness <= 0.0f) return {0.0f, Vec3f::Zero(), c.nearest_cell};
  const Vec3f towards = gradient / steepness;
  // Fissures along the trunk open wide; cracks across it (leaving the fissure vertically) stay narrow;
  // and each fissure widens and narrows along its way (0.4 to 1.6 of its width).
  const float across_share = 1.0f - towards.z() * towards.z();
  const float g = 1.3f * b.across;
  const float opening = 0.4f + 1.2f * value_noise3(p.x() * g, p.y() * g, p.z() * g, kBarkFurrow + 4);
  return {(c.f2 - c.f1) / steepness / ((0.35f + 0.65f * across_share) * opening), towards, c.nearest_cell};
}

/// Albedo of plated bark at s over `plate` (null where the pattern does not show: the mean look):
/// plates of its colour, each a little lighter or darker, fissures of theirs, fine grain.
Vec3f plated(const SurfacePoint& s, const Plated& b, const PlateSample* plate) {
  const Vec3f& p = s.position;
  const float grain = value_noise3(p.x() * 40.0f, p.y() * 40.0f, p.z() * 12.0f, kBarkPlate);
  float fissure = b.mean_fissure, tone = 1.0f;
  const float detail = plate_detail(b, s.footprint);
  if (plate) {
    fissure += (plate->fissure(b.width) - b.mean_fissure) * detail;
    // Flaking patches and fine grooves along the trunk on each plate's face.
    const float flakes = value_noise3(p.x() * 25.0f, p.y() * 25.0f, p.z() * 8.0f, kBarkPlate + 2);
    const float grooves = value_noise3(p.x() * 70.0f, p.y() * 70.0f, p.z() * 3.0f, kBarkPlate + 3);
    tone += (b.tone * (lattice_value(plate->plate) - 0.5f) + 0.5f * (flakes - 0.5f) + 0.4f * (grooves - 0.5f)) * detail;
  }
  return lerp(Vec3f(b.r, b.g, b.b) * tone, Vec3f(b.fr, b.fg, b.fb), fissure) * (0.85f + 0.3f * grain);
}

/// Relief gradient of plated bark `relief_share` of its full depth over `plate` (null: none).
Vec3f plated_slope(const SurfacePoint& s, const Plated& b, const PlateSample* plate, float relief_share) {
  if (!plate) return Vec3f::Zero();
  const float depth = b.relief * relief_share * plate_detail(b, s.footprint);
  const float t = plate->metres / b.width;
  if (t >= 1.0f) return Vec3f::Zero();  // on a plate's flat top
  // The height depth * (smoothstep(0, width, d) - 1) rises out of the fissure along d's gradient.
  const float rise = std::min(depth * 6.0f * t * (1.0f - t) / b.width, kMaxBarkSlope);
  return plate->towards_plate * rise;
}

/// Share of a pine's bark that is the thin orange upper bark (0 low on the trunk, 1 from about 50 %).
float pine_upper_share(const SurfacePoint& s) {
  const Vec3f& p = s.position;
  const float wobble = 0.12f * (fbm3(p.x() * 1.5f, p.y() * 1.5f, p.z() * 0.5f, 2, kBarkBlotch) - 0.5f);
  return smoothstep(0.3f, 0.5f, s.uv.y() + wobble);
}

/// Share of a birch's bark that is white (0 on the dark fissured base, 1 from about 14 % of the height).
float birch_white_share(const SurfacePoint& s) {
  const Vec3f& p = s.position;
  const float wobble = 0.06f * (fbm3(p.x() * 2.0f, p.y() * 2.0f, p.z() * 0.6f, 2, kBarkBlotch + 1) - 0.5f);
  return smoothstep(0.06f, 0.14f, s.uv.y() + wobble);
}

/// Scots pine's thin orange flaking upper bark (from about 40 % of the height).
Vec3f pine_upper(const SurfacePoint& s) {
  const Vec3f& p = s.position;
  const float flake = value_noise3(p.x() * 18.0f, p.y() * 18.0f, p.z() * 6.0f, kBarkPlate + 1);
  return Vec3f(0.46f, 0.2f, 0.07f) * (0.75f + 0.35f * flake);
}

/// Silver birch's white bark with dark horizontal lenticels and black patches (above its dark fissured base).
Vec3f birch_white(const SurfacePoint& s) {
  const Vec3f& p = s.position;
  Vec3f c = Vec3f(0.55f, 0.54f, 0.5f) * (0.9f + 0.1f * value_noise3(p.x() * 8.0f, p.y() * 8.0f, p.z() * 8.0f, kBarkPlate));
  const float dash = value_noise3(p.x() * 5.0f, p.y() * 5.0f, p.z() * 45.0f, kBarkMark);
  c = lerp(c, Vec3f(0.06f, 0.055f, 0.05f), smoothstep(0.78f, 0.84f, dash));
  const float patch = fbm3(p.x() * 2.5f, p.y() * 2.5f, p.z() * 1.2f, 3, kBarkBlotch);
  return lerp(c, Vec3f(0.05f, 0.045f, 0.04f), smoothstep(0.68f, 0.74f, patch));
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

bool is_species_bark(Material m) {
  switch (m) {
    case Material::BarkSpruce:
    case Material::BarkPine:
    case Material::BarkLarch:
    case Material::BarkBeech:
    case Material::BarkBirch:
    case Material::BarkOak: return true;
    default: return false;
  }
}

SpeciesBark species_bark(const SurfacePoint& s) {
  const Plated* b = nullptr;
  float upper = 0.0f;  // share of the bark above the plates: pine's orange flakes, birch's white
  switch (s.material) {
    case Material::BarkSpruce: b = &kSpruceScales; break;
    case Material::BarkPine: b = &kPinePlates, upper = pine_upper_share(s); break;
    case Material::BarkLarch: b = &kLarchPlates; break;
    case Material::BarkOak: b = &kOakRidges; break;
    case Material::BarkBirch: b = &kBirchBase, upper = birch_white_share(s); break;
    case Material::BarkBeech: return {beech(s), Vec3f::Zero()};
    default: return {Vec3f(0.5f, 0.0f, 0.5f), Vec3f::Zero()};
  }
  const Vec3f above = upper <= 0.0f                     ? Vec3f::Zero()
                      : s.material == Material::BarkPine ? pine_upper(s)
                                                         : birch_white(s);
  if (upper >= 1.0f) return {above, Vec3f::Zero()};
  // One plate lookup for the colour and the relief, where the pattern shows.
  std::optional<PlateSample> plate;
  if (plate_detail(*b, s.footprint) > 0.0f) plate = plate_at(s.position, *b);
  const PlateSample* shown = plate ? &*plate : nullptr;
  const Vec3f low = plated(s, *b, shown);
  return {upper > 0.0f ? lerp(low, above, upper) : low, plated_slope(s, *b, shown, 1.0f - upper)};
}

}  // namespace silva::render
