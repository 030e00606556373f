#include "render/floor_litter.hpp"

#include <algorithm>
#include <cmath>

#include "core/value_noise.hpp"
#include "render/materials.hpp"

namespace silva::render {

namespace {

/// Byte `shift / 8` of hash `h` as a value in [0, 1].
float byte_value(uint32_t h, int shift) { return float((h >> shift) & 255u) * (1.0f / 255.0f); }

/// Share of the pixel's box [x - f/2, x + f/2] (half_f = f/2, inv_f = 1/f) inside the band [-w, w].
float band_cover(float x, float w, float half_f, float inv_f) {
  return std::min(std::max(std::min(w, x + half_f) - std::max(-w, x - half_f), 0.0f) * inv_f, 1.0f);
}

/// One sprite's shape, colour and tilt, drawn from its cell's two hashes.
struct Sprite {
  float half_length, half_width_at_middle, tilt, curl, keep;
  bool leaf, cone, taper;  ///< A leaf (midrib, curl); a cone (seams, round); narrowing to pointed ends.
  Vec3f colour;
  float pitch = kLitterConePitch;             ///< A cone's seam spacing.
  float shadow_width = kLitterShadowWidth;     ///< Width of its contact shadow,
  float reach = kLitterReach;                  ///< and how far that and a filter reach past its outline.
};

/// The kinds' constants: leaf, blade, needle, twig, cone.
struct KindTable {
  const float* leaf;
  const float* blade;
  const float* needle;
  const float* twig;
  const float* cone;
};

/// Distance (metres) from q pitches along to the nearest seam (a whole number of pitches `pitch` metres apart).
float seam_distance(float q, float pitch) { return std::abs(q - std::floor(q + 0.5f)) * pitch; }

/// The sprite of cell hashes h1, h2 over a floor of `m`.
Sprite sprite_of(uint32_t h1, uint32_t h2, const LitterMix& m) {
  const float size = byte_value(h2, 0), hue = byte_value(h2, 8), kind = byte_value(h2, 16), pick = byte_value(h2, 24);
  const float untwigged = 1.0f - kLitterTwigShare;
  const bool twig = kind >= untwigged;
  const bool cone = !twig && kind >= untwigged - kLitterConeShare * m.needles;
  const bool blade = !twig && !cone && kind < m.grass * untwigged;
  const bool needle = !twig && !cone && !blade && kind < (m.grass + m.needles * (1.0f - m.grass)) * untwigged;
  Sprite s{};
  s.leaf = !twig && !cone && !blade && !needle;
  s.cone = cone;
  s.taper = s.leaf || blade || cone;
  s.keep = pick < kLitterDensity ? 1.0f : 0.0f;
  s.tilt = (byte_value(h1 ^ h2, 4) * 2.0f - 1.0f) * kLitterTilt;
  s.curl = s.leaf ? kLitterCurl : 0.0f;
  const auto of = [&](const KindTable& t) {
    return s.leaf ? t.leaf : cone ? t.cone : blade ? t.blade : needle ? t.needle : t.twig;
  };
  const float* half = of({kLitterLeafHalf, kLitterBladeHalf, kLitterNeedleHalf, kLitterTwigHalf, kLitterConeHalf});
  s.half_length = half[0] + half[1] * size;
  const float width = kLitterLeafWidth[0] + kLitterLeafWidth[1] * byte_value(h1 ^ h2, 12);
  s.half_width_at_middle = s.leaf   ? width * s.half_length
                           : cone   ? kLitterConeWidth * s.half_length
                           : blade  ? kLitterBladeHalfWidth[0] + kLitterBladeHalfWidth[1] * hue
                           : needle ? kLitterNeedleHalfWidth
                                    : kLitterTwigHalfWidth[0] + kLitterTwigHalfWidth[1] * hue;
  const bool is_fresh = s.leaf && pick < kLitterDensity * m.fresh;
  const float* dark = is_fresh ? kGroundFallenOrange
                               : of({kLitterLeafDark, kLitterBladeDark, kLitterNeedleDark, kLitterTwigDark, kLitterConeDark});
  const float* light = is_fresh ? kGroundFallenYellow
                                : of({kLitterLeafLight, kLitterBladeLight, kLitterNeedleLight, kLitterTwigLight, kLitterConeLight});
  for (int k = 0; k < 3; ++k) s.colour[k] = mix(dark[k], light[k], hue);
  return s;
}

/// Lays sprite `s` (cell hash h1), whose centre is (rx, ry) metres from the point, over `c` and `slope`.
void lay_sprite(const Sprite& s, uint32_t h1, float rx, float ry, float half_f, float inv_f, float weight, Vec3f& c,
                Vec2f& slope) {
  const float reach_u = s.half_length + s.reach + half_f, reach_v = s.half_width_at_middle + s.reach + half_f;
  if (s.keep == 0.0f || rx * rx + ry * ry >= reach_u * reach_u + reach_v * reach_v) return;  // it does not reach here
  const float ax = byte_value(h1, 16) * 2.0f - 1.0f, ay = byte_value(h1, 24) * 2.0f - 1.0f;
  const float len = std::sqrt(ax * ax + ay * ay + 1e-8f);
  const float ux = ax / len, uy = ay / len;
  const float u = rx * ux + ry * uy, across = ry * ux - rx * uy, v = std::abs(across);
  const float t = u / s.half_length;
  const float half_width = s.taper ? s.half_width_at_middle * (1.0f - t * t) : s.half_width_at_middle;
  const float presence = s.keep * weight;
  const float cover = band_cover(v, half_width, half_f, inv_f) * band_cover(u, s.half_length, half_f, inv_f) * presence;
  const float shadow = band_cover(v, half_width + s.shadow_width, half_f, inv_f) *
                       band_cover(u, s.half_length + s.shadow_width, half_f, inv_f) * presence;
  const float rib =
      s.leaf ? band_cover(v, kLitterRibHalfWidth, half_f, inv_f) * band_cover(u, 0.9f * s.half_length, half_f, inv_f) : 0.0f;
  // A cone's scales: two sets of diagonal seams, the darker of them.
  const float seam =
      s.cone ? std::max(band_cover(seam_distance((u + across) * (1.0f / s.pitch), s.pitch), kLitterConeSeamHalfWidth, half_f, inv_f),
                        band_cover(seam_distance((u - across) * (1.0f / s.pitch), s.pitch), kLitterConeSeamHalfWidth, half_f, inv_f))
             : 0.0f;
  for (int k = 0; k < 3; ++k) {
    const float under = c[k] * (1.0f - kLitterShadow * shadow);
    c[k] = mix(under, s.colour[k] * (1.0f - kLitterRib * rib) * (1.0f - kLitterConeSeam * seam), cover);
  }
  // Each half of a curled leaf slopes away from the midrib; a cone's flank steepens towards its outline.
  const float side = s.cone ? kLitterConeRound * std::clamp(across / std::max(half_width, 1e-6f), -1.0f, 1.0f)
                            : std::copysign(s.curl, across);
  slope = Vec2f(mix(slope.x(), ux * s.tilt - uy * side, cover), mix(slope.y(), uy * s.tilt + ux * side, cover));
}

/// The spruce cone of cell hashes h1, h2 where a cell holds one with probability kSpruceConeShare x density.
Sprite spruce_cone_of(uint32_t h1, uint32_t h2, float density) {
  const float size = byte_value(h2, 0), hue = byte_value(h2, 8), pick = byte_value(h2, 24);
  Sprite s{};
  s.cone = s.taper = true;
  s.keep = pick < kSpruceConeShare * density ? 1.0f : 0.0f;
  s.tilt = (byte_value(h1 ^ h2, 4) * 2.0f - 1.0f) * kLitterTilt;
  s.half_length = kSpruceConeHalf[0] + kSpruceConeHalf[1] * size;
  s.half_width_at_middle = kSpruceConeWidth * s.half_length;
  for (int k = 0; k < 3; ++k) s.colour[k] = mix(kSpruceConeDark[k], kSpruceConeLight[k], hue);
  s.pitch = kSpruceConePitch;
  s.shadow_width = kSpruceConeShadowWidth;
  s.reach = kSpruceConeReach;
  return s;
}

/// Calls lay(h1, h2, rx, ry) for the cell of point (x, y) on a grid of `cell` metres and the eight around it
/// (rows of cells upwards, each from the left): h1, h2 the cell's hashes (lattice z = z, z + 1 with `salt`),
/// (rx, ry) the point's offset in metres from the sprite centre the cell's h1 places.
template <class Lay>
void each_cell_around(float x, float y, float cell, int32_t z, uint32_t salt, Lay lay) {
  const float gx = x * (1.0f / cell), gy = y * (1.0f / cell);
  const float fx = std::floor(gx), fy = std::floor(gy);
  const int32_t ix = int32_t(fx), iy = int32_t(fy);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const uint32_t h1 = lattice_hash(ix + dx, iy + dy, z, salt);
      const uint32_t h2 = lattice_hash(ix + dx, iy + dy, z + 1, salt);
      lay(h1, h2, (gx - (fx + float(dx)) - byte_value(h1, 0)) * cell, (gy - (fy + float(dy)) - byte_value(h1, 8)) * cell);
    }
}

}  // namespace

float litter_fade(float footprint) {
  const float t = std::clamp((footprint - kLitterFadeNear) / (kLitterFadeFar - kLitterFadeNear), 0.0f, 1.0f);
  return 1.0f - smooth_weight(t);
}

float spruce_cone_fade(float footprint) {
  const float t = std::clamp((footprint - kSpruceConeFadeNear) / (kSpruceConeFadeFar - kSpruceConeFadeNear), 0.0f, 1.0f);
  return 1.0f - smooth_weight(t);
}

void litter_sprites(float x, float y, float footprint, const LitterMix& litter, float weight, Vec3f& c, Vec2f& slope) {
  if (!(weight > 0.0f)) return;
  const float f = std::clamp(footprint, 1e-4f, kLitterWidestFilter);
  const float half_f = 0.5f * f, inv_f = 1.0f / f;
  for (int layer = 0; layer < kLitterLayers; ++layer)
    each_cell_around(x, y, kLitterCell, 2 * layer, kGroundLitterSalt, [&](uint32_t h1, uint32_t h2, float rx, float ry) {
      lay_sprite(sprite_of(h1, h2, litter), h1, rx, ry, half_f, inv_f, weight, c, slope);
    });
}

void spruce_cones(float x, float y, float footprint, float density, float weight, Vec3f& c, Vec2f& slope) {
  if (!(weight > 0.0f) || !(density > 0.0f)) return;
  const float f = std::clamp(footprint, 1e-4f, kSpruceConeWidestFilter);
  const float half_f = 0.5f * f, inv_f = 1.0f / f;
  each_cell_around(x, y, kSpruceConeCell, 0, kGroundConeSalt, [&](uint32_t h1, uint32_t h2, float rx, float ry) {
    lay_sprite(spruce_cone_of(h1, h2, density), h1, rx, ry, half_f, inv_f, weight, c, slope);
  });
}

}  // namespace silva::render
