#include "render/trail_material.hpp"

#include <algorithm>
#include <cmath>

#include "render/noise_salts.hpp"
#include "core/value_noise.hpp"
#include "core/surface_overlay.hpp"

namespace silva::render {

namespace {

/// A scatter of stones: one chance per square cell, the centre kept inside its cell.
struct StoneField {
  float cell;     ///< Cell edge, metres.
  float chance;   ///< Share of cells holding a stone.
  float r_min;    ///< Smallest radius, metres ...
  float r_span;   ///< ... plus up to this much (squared distribution: mostly small).
  uint32_t salt;  ///< Noise salt.
  Vec3f tint;     ///< Colour of a mid-toned stone ...
  Vec3f tint_alt; ///< ... blended per stone towards this one.
};

/// Stones set in packed earth and roots: mostly small, a few fist-sized, warm grey.
const StoneField kEmbeddedStones{0.3f, 0.13f, 0.03f, 0.05f, kTrailStone, {0.22f, 0.19f, 0.15f}, {0.22f, 0.19f, 0.15f}};
/// Gravel: small stones packed edge to edge, grey to ochre.
const StoneField kGravelStones{0.06f, 0.8f, 0.012f, 0.018f, kTrailGravel, {0.25f, 0.245f, 0.23f}, {0.3f, 0.24f, 0.16f}};

/// Roots crossing the trail: one chance per stretch of arc length.
struct RootField {
  float spacing;     ///< Metres of arc length per chance.
  float chance;      ///< Share of chances that hold a root.
  float thick_min;   ///< Smallest half thickness, metres ...
  float thick_span;  ///< ... plus up to this much.
};

/// A few roots over packed earth and leaf litter.
constexpr RootField kSparseRoots{2.2f, 0.4f, 0.02f, 0.03f};
/// An eroded, rooty trail: roots every metre or so, thicker.
constexpr RootField kDenseRoots{0.7f, 0.85f, 0.025f, 0.045f};
/// Colour of roots in the soil.
const Vec3f kRootBark(0.12f, 0.085f, 0.055f);

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

/// Stone of field `f` at p, as a weight in [0, 1] and its colour (none: weight 0).
float stone(const Vec3f& p, const StoneField& f, Vec3f& colour) {
  const float fx = std::floor(p.x() / f.cell), fy = std::floor(p.y() / f.cell);
  const int32_t ix = int32_t(fx), iy = int32_t(fy);
  if (lattice_value(lattice_hash(ix, iy, 0, f.salt)) > f.chance) return 0.0f;
  const float cx = (fx + 0.3f + 0.4f * lattice_value(lattice_hash(ix, iy, 1, f.salt))) * f.cell;
  const float cy = (fy + 0.3f + 0.4f * lattice_value(lattice_hash(ix, iy, 2, f.salt))) * f.cell;
  const float size = lattice_value(lattice_hash(ix, iy, 3, f.salt));
  const float radius = f.r_min + f.r_span * size * size;
  const float dx = p.x() - cx, dy = p.y() - cy;
  // A lumpy outline: the radius varies with a noise over the stone's own scale.
  const float k = 1.5f / radius;
  const float lump = 0.75f + 0.5f * value_noise2(dx * k + 7.3f * fx, dy * k + 3.1f * fy, f.salt + 5);
  const float r = std::sqrt(dx * dx + dy * dy) / (radius * lump);
  if (r >= 1.0f) return 0.0f;
  const float tone = 0.6f + 0.45f * lattice_value(lattice_hash(ix, iy, 4, f.salt));
  const Vec3f tint = lerp(f.tint, f.tint_alt, lattice_value(lattice_hash(ix, iy, 6, f.salt)));
  // Lighter on top, darker where it meets the soil (it sits in the ground).
  colour = tint * (tone * (1.1f - 0.55f * r * r));
  return smoothstep(1.0f, 0.8f, r);
}

/// Root of field `f` crossing the trail near arc length s at p (edge coordinate `edge`), as a weight
/// in [0, 1] (0: none) and its shade across its width in `shade` (rounded: lighter along its top).
float root(const Vec3f& p, float s, float edge, const RootField& f, float& shade) {
  const float cell = std::floor(s / f.spacing);
  const uint32_t h = lattice_hash(int32_t(cell), 0, 0, kTrailRoot);
  if (lattice_value(h) > f.chance) return 0.0f;
  const float at = (cell + 0.2f + 0.6f * lattice_value(lattice_hash(int32_t(cell), 1, 0, kTrailRoot))) * f.spacing;
  const float wander = 0.8f * (fbm2(p.x() * 1.1f, p.y() * 1.1f, 3, kTrailRoot + 2) - 0.5f);
  const float thickness = f.thick_min + f.thick_span * lattice_value(lattice_hash(int32_t(cell), 2, 0, kTrailRoot));
  const float d = std::abs(s - at - wander) / thickness;
  if (d >= 1.0f) return 0.0f;
  shade = 1.25f - 0.6f * d * d;
  // Half the roots reach in from the edge only and end in the soil (edge coordinate below -reach).
  const float reach = 0.25f + 1.5f * lattice_value(lattice_hash(int32_t(cell), 3, 0, kTrailRoot));
  return smoothstep(1.0f, 0.7f, d) * smoothstep(-reach - 0.15f, -reach, edge);
}

/// `c` with the forest floor's litter drifting in over the band's outer ~0.35 m.
Vec3f drift_litter(const Vec3f& c, const Vec3f& p, const Vec3f& floor, float edge) {
  const float litter = fbm2(p.x() * 2.5f, p.y() * 2.5f, 2, kTrailLitter);
  return lerp(c, floor, 0.7f * smoothstep(-0.35f, 0.0f, edge + 0.3f * (litter - 0.5f)));
}

/// `c` with the stones of field `f` set into it.
Vec3f with_stones(const Vec3f& c, const Vec3f& p, const StoneField& f) {
  Vec3f rock;
  const float st = stone(p, f, rock);
  return st > 0.0f ? lerp(c, rock, st) : c;
}

/// `c` with the roots of field `f`, of colour `bark`, crossing it.
Vec3f with_roots(const Vec3f& c, const SurfacePoint& s, float edge, const RootField& f, const Vec3f& bark) {
  float shade = 1.0f;
  const float rt = root(s.position, s.uv.y(), edge, f, shade);
  return rt > 0.0f ? lerp(c, bark * shade, rt) : c;
}

/// Weight of the two wheel or boot ruts at distance `in` (metres) inside the nearer edge: a band
/// from 0.12 to ~0.5 m in, its inner side ragged.
float rut(float in, const Vec3f& p) {
  const float ragged = 0.12f * (value_noise2(p.x() * 1.7f, p.y() * 1.7f, kTrailRut) - 0.5f);
  return smoothstep(0.06f, 0.14f, in) * (1.0f - smoothstep(0.42f, 0.52f, in + ragged));
}

/// Packed earth: soil, litter drifting in near the edge, embedded stones, a few roots.
Vec3f packed_earth(const SurfacePoint& s, const Vec3f& floor, float edge) {
  const Vec3f c = with_stones(drift_litter(soil(s.position), s.position, floor, edge), s.position, kEmbeddedStones);
  return with_roots(c, s, edge, kSparseRoots, kRootBark);
}

/// Gravel: a grey-beige bed of small packed stones with a few larger ones, litter at the edges.
Vec3f gravel(const SurfacePoint& s, const Vec3f& floor, float edge) {
  const Vec3f& p = s.position;
  const float patch = fbm2(p.x() * 1.3f, p.y() * 1.3f, 2, kTrailGravel + 8);
  const Vec3f bed = Vec3f(0.2f, 0.18f, 0.15f) * (0.8f + 0.35f * patch);
  const Vec3f c = with_stones(with_stones(bed, p, kGravelStones), p, kEmbeddedStones);
  return drift_litter(c, p, floor, edge);
}

/// Roots: eroded soil crossed by many dark roots, washed-out stones between them.
Vec3f rooty(const SurfacePoint& s, const Vec3f& floor, float edge) {
  const Vec3f eroded = soil(s.position).cwiseProduct(Vec3f(0.7f, 0.64f, 0.6f));
  const Vec3f c = with_stones(drift_litter(eroded, s.position, floor, edge), s.position, kEmbeddedStones);
  return with_roots(c, s, edge, kDenseRoots, Vec3f(0.085f, 0.062f, 0.04f));
}

/// Leaf-covered: the floor's litter over the band, soil showing along the trodden middle, a few roots.
Vec3f leaf_covered(const SurfacePoint& s, const Vec3f& floor, float edge) {
  const Vec3f& p = s.position;
  const float scuff = fbm2(p.x() * 1.2f, p.y() * 1.2f, 2, kTrailLitter + 8);
  const float trodden = 0.65f * smoothstep(0.3f, 0.6f, -edge + 0.4f * (scuff - 0.5f));
  return with_roots(lerp(floor, soil(p), trodden), s, edge, kSparseRoots, kRootBark);
}

/// Muddy: dark mud, darker and smoother in the two ruts, litter at the edges.
Vec3f muddy(const SurfacePoint& s, const Vec3f& floor, float edge) {
  const Vec3f& p = s.position;
  const float patch = fbm2(p.x() * 0.8f, p.y() * 0.8f, 2, kTrailRut + 4);
  const float grit = value_noise2(p.x() * 20.0f, p.y() * 20.0f, kTrailRut + 8);
  const Vec3f mud = Vec3f(0.072f, 0.052f, 0.034f) * ((0.8f + 0.4f * patch) * (0.92f + 0.16f * grit));
  return drift_litter(mud * (1.0f - 0.25f * rut(-edge, p)), p, floor, edge);
}

/// Grass ruts: two bare ruts of soil, short grass (blade-scale grain, litter showing through) between
/// them and along the edges.
Vec3f grass_ruts(const SurfacePoint& s, const Vec3f& floor, float edge) {
  const Vec3f& p = s.position;
  const float patch = fbm2(p.x() * 3.0f, p.y() * 3.0f, 2, kTrailRut + 12);
  const float blades = value_noise2(p.x() * 45.0f, p.y() * 45.0f, kTrailRut + 16);
  const Vec3f turf = Vec3f(0.06f, 0.075f, 0.028f) * ((0.7f + 0.6f * patch) * (0.75f + 0.5f * blades));
  const Vec3f grass = lerp(floor, turf, 0.75f);
  const Vec3f bare = soil(p) * 0.85f;
  return drift_litter(lerp(grass, bare, rut(-edge, p)), p, floor, edge);
}

/// Pure trail surface of the point's family at s (weight 1).
Vec3f trail_surface(const SurfacePoint& s, const Vec3f& floor, float edge) {
  switch (s.trail) {
    case TrailSurface::Gravel: return gravel(s, floor, edge);
    case TrailSurface::Roots: return rooty(s, floor, edge);
    case TrailSurface::LeafCovered: return leaf_covered(s, floor, edge);
    case TrailSurface::Muddy: return muddy(s, floor, edge);
    case TrailSurface::GrassRuts: return grass_ruts(s, floor, edge);
    case TrailSurface::PackedEarth: break;
  }
  return packed_earth(s, floor, edge);
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
  ground_albedo_row(&s.position, &s.normal, &s.footprint, 1, &floor, nullptr, nullptr, s.floor);
  return trail_albedo_on(s, floor);
}

Vec3f trail_albedo_on(const SurfacePoint& s, const Vec3f& floor) {
  const float edge = overlay_edge(s.uv.x(), s.position);
  const float w = overlay_weight(edge);
  const Vec3f outside = worn_floor(s.position, floor, edge);
  return w > 0.0f ? lerp(outside, trail_surface(s, floor, edge), w) : outside;
}

float trail_standing_water(const SurfacePoint& s) {
  if (s.trail != TrailSurface::Muddy || s.material != Material::Trail) return 0.0f;
  const float edge = overlay_edge(s.uv.x(), s.position);
  const float in_rut = rut(-edge, s.position);
  if (in_rut <= 0.0f) return 0.0f;
  // Pools stretched along the ruts: slow along the arc length, quick across.
  const float pool = value_noise2(s.uv.y() * 0.45f, s.uv.x() * 2.0f, kTrailWater);
  return in_rut * smooth_weight(std::clamp((pool - 0.55f) * 8.0f, 0.0f, 1.0f));
}

}  // namespace silva::render
