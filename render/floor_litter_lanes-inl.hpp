// render/floor_litter.hpp's litter_sprites on Highway lanes, one floor point per lane, with the scalar
// function's operations in the same order and no MulAdd (every target gives the same bits). Included
// once per target (Highway's -inl convention) after render/shading_noise_lanes-inl.hpp.
#if defined(SILVA_RENDER_FLOOR_LITTER_LANES_INL_HPP) == defined(HWY_TARGET_TOGGLE)
#ifdef SILVA_RENDER_FLOOR_LITTER_LANES_INL_HPP
#undef SILVA_RENDER_FLOOR_LITTER_LANES_INL_HPP
#else
#define SILVA_RENDER_FLOOR_LITTER_LANES_INL_HPP
#endif

#include "hwy/highway.h"
#include "render/floor_litter.hpp"
#include "render/materials.hpp"

HWY_BEFORE_NAMESPACE();
namespace silva::render::HWY_NAMESPACE {

/// floor_litter.cpp's byte_value on lanes: byte `shift / 8` of `h` in [0, 1].
inline VF byte_value_lanes(VU h, int shift) {
  const DU du;
  const VU byte = hn::And(hn::ShiftRightSame(h, shift), hn::Set(du, 255u));
  return hn::Mul(hn::ConvertTo(DF(), hn::BitCast(DI(), byte)), hn::Set(DF(), 1.0f / 255.0f));
}

/// floor_litter.cpp's band_cover on lanes.
inline VF band_cover_lanes(VF x, VF w, VF half_f, VF inv_f) {
  const DF d;
  const VF inside = hn::Sub(hn::Min(w, hn::Add(x, half_f)), hn::Max(hn::Neg(w), hn::Sub(x, half_f)));
  return hn::Min(hn::Mul(hn::Max(inside, hn::Zero(d)), inv_f), hn::Set(d, 1.0f));
}

/// floor_litter.hpp's LitterMix on lanes, with the litter's weight.
struct LitterMixLanes {
  VF grass, needles, fresh, weight;
};

/// A sprite of each lane (floor_litter.cpp's Sprite) with its kind masks.
struct SpriteLanes {
  hn::Mask<DF> leaf, cone, blade, needle, taper, fresh;
  VF half_length, middle, tilt, keep, hue;
};

/// The constant of each sprite kind on lanes: a leaf, cone, blade, needle or twig where the masks say.
inline VF per_kind(const SpriteLanes& s, float leaf, float blade, float needle, float twig, float cone) {
  const DF d;
  return hn::IfThenElse(
      s.leaf, hn::Set(d, leaf),
      hn::IfThenElse(s.cone, hn::Set(d, cone),
                     hn::IfThenElse(s.blade, hn::Set(d, blade), hn::IfThenElse(s.needle, hn::Set(d, needle), hn::Set(d, twig)))));
}

/// floor_litter.cpp's seam_distance on lanes.
inline VF seam_distance_lanes(VF q, VF pitch) {
  const DF d;
  return hn::Mul(hn::Abs(hn::Sub(q, hn::Floor(hn::Add(q, hn::Set(d, 0.5f))))), pitch);
}

/// What differs between sprite layers: their cones' seam spacing and dark and light colours, and every
/// sprite's contact shadow width and reach past its outline (kLitterShadowWidth, kLitterReach).
struct LayerLook {
  float pitch;
  const float* dark;
  const float* light;
  float shadow_width, reach;
};

/// floor_litter.cpp's sprite_of on lanes (the colours are picked where the sprite is laid).
inline SpriteLanes sprite_lanes(VU h1, VU h2, const LitterMixLanes& m) {
  const DF d;
  const VF one = hn::Set(d, 1.0f), two = hn::Set(d, 2.0f);
  const VF size = byte_value_lanes(h2, 0), kind = byte_value_lanes(h2, 16), pick = byte_value_lanes(h2, 24);
  SpriteLanes s;
  s.hue = byte_value_lanes(h2, 8);
  const VF untwigged = hn::Set(d, 1.0f - kLitterTwigShare);
  const auto twig = hn::Ge(kind, untwigged);
  s.cone = hn::AndNot(twig, hn::Ge(kind, hn::Sub(untwigged, hn::Mul(hn::Set(d, kLitterConeShare), m.needles))));
  const auto twig_or_cone = hn::Or(twig, s.cone);
  s.blade = hn::AndNot(twig_or_cone, hn::Lt(kind, hn::Mul(m.grass, untwigged)));
  const VF needle_bound = hn::Mul(hn::Add(m.grass, hn::Mul(m.needles, hn::Sub(one, m.grass))), untwigged);
  s.needle = hn::AndNot(hn::Or(twig_or_cone, s.blade), hn::Lt(kind, needle_bound));
  s.leaf = hn::Not(hn::Or(hn::Or(twig_or_cone, s.blade), s.needle));
  s.taper = hn::Or(hn::Or(s.leaf, s.blade), s.cone);
  s.keep = hn::IfThenElseZero(hn::Lt(pick, hn::Set(d, kLitterDensity)), one);
  s.tilt = hn::Mul(hn::Sub(hn::Mul(byte_value_lanes(hn::Xor(h1, h2), 4), two), one), hn::Set(d, kLitterTilt));
  s.half_length =
      hn::Add(per_kind(s, kLitterLeafHalf[0], kLitterBladeHalf[0], kLitterNeedleHalf[0], kLitterTwigHalf[0], kLitterConeHalf[0]),
              hn::Mul(per_kind(s, kLitterLeafHalf[1], kLitterBladeHalf[1], kLitterNeedleHalf[1], kLitterTwigHalf[1], kLitterConeHalf[1]),
                      size));
  const VF width = hn::Add(hn::Set(d, kLitterLeafWidth[0]), hn::Mul(hn::Set(d, kLitterLeafWidth[1]), byte_value_lanes(hn::Xor(h1, h2), 12)));
  const VF blade_width = hn::Add(hn::Set(d, kLitterBladeHalfWidth[0]), hn::Mul(hn::Set(d, kLitterBladeHalfWidth[1]), s.hue));
  const VF twig_width = hn::Add(hn::Set(d, kLitterTwigHalfWidth[0]), hn::Mul(hn::Set(d, kLitterTwigHalfWidth[1]), s.hue));
  s.middle = hn::IfThenElse(
      s.leaf, hn::Mul(width, s.half_length),
      hn::IfThenElse(s.cone, hn::Mul(hn::Set(d, kLitterConeWidth), s.half_length),
                     hn::IfThenElse(s.blade, blade_width, hn::IfThenElse(s.needle, hn::Set(d, kLitterNeedleHalfWidth), twig_width))));
  s.fresh = hn::And(s.leaf, hn::Lt(pick, hn::Mul(hn::Set(d, kLitterDensity), m.fresh)));
  return s;
}

/// floor_litter.cpp's lay_sprite on lanes: sprite `s` (cell hash h1), its centre (rx, ry) metres from
/// each lane's point, over the lanes' colours `c` and slope (sx, sy); `frame` = {half_f, inv_f}; the
/// layer's cones and shadows look as `look` says.
inline void lay_sprite_lanes(const SpriteLanes& s, VU h1, VF rx, VF ry, const VF* frame, VF weight, const LayerLook& look,
                             VF* c, VF& sx, VF& sy) {
  const DF d;
  const VF one = hn::Set(d, 1.0f), two = hn::Set(d, 2.0f);
  const VF reach = hn::Set(d, look.reach);
  const VF reach_u = hn::Add(hn::Add(s.half_length, reach), frame[0]), reach_v = hn::Add(hn::Add(s.middle, reach), frame[0]);
  const auto near = hn::And(hn::Gt(s.keep, hn::Zero(d)), hn::Lt(hn::Add(hn::Mul(rx, rx), hn::Mul(ry, ry)),
                                                               hn::Add(hn::Mul(reach_u, reach_u), hn::Mul(reach_v, reach_v))));
  if (hn::AllFalse(d, near)) return;  // it reaches none of the points (the lanes it misses gain nothing from it)
  const VF ax = hn::Sub(hn::Mul(byte_value_lanes(h1, 16), two), one), ay = hn::Sub(hn::Mul(byte_value_lanes(h1, 24), two), one);
  const VF len = hn::Sqrt(hn::Add(hn::Add(hn::Mul(ax, ax), hn::Mul(ay, ay)), hn::Set(d, 1e-8f)));
  const VF ux = hn::Div(ax, len), uy = hn::Div(ay, len);
  const VF u = hn::Add(hn::Mul(rx, ux), hn::Mul(ry, uy)), across = hn::Sub(hn::Mul(ry, ux), hn::Mul(rx, uy));
  const VF v = hn::Abs(across);
  const VF t = hn::Div(u, s.half_length);
  const VF half_width = hn::IfThenElse(s.taper, hn::Mul(s.middle, hn::Sub(one, hn::Mul(t, t))), s.middle);
  const VF presence = hn::Mul(s.keep, weight);
  const VF cover = hn::Mul(hn::Mul(band_cover_lanes(v, half_width, frame[0], frame[1]),
                                   band_cover_lanes(u, s.half_length, frame[0], frame[1])), presence);
  const VF rim = hn::Set(d, look.shadow_width);
  const VF shadow = hn::Mul(hn::Mul(band_cover_lanes(v, hn::Add(half_width, rim), frame[0], frame[1]),
                                    band_cover_lanes(u, hn::Add(s.half_length, rim), frame[0], frame[1])), presence);
  const VF rib = hn::IfThenElseZero(s.leaf, hn::Mul(band_cover_lanes(v, hn::Set(d, kLitterRibHalfWidth), frame[0], frame[1]),
                                                    band_cover_lanes(u, hn::Mul(hn::Set(d, 0.9f), s.half_length), frame[0], frame[1])));
  const VF rib_shade = hn::Sub(one, hn::Mul(hn::Set(d, kLitterRib), rib));
  const bool any_cone = !hn::AllFalse(d, s.cone);  // cones are few: skip their terms when no lane has one
  VF seam = hn::Zero(d);
  if (any_cone) {
    const VF pitch = hn::Set(d, look.pitch), inv_pitch = hn::Set(d, 1.0f / look.pitch);
    const VF seam_width = hn::Set(d, kLitterConeSeamHalfWidth);
    seam = hn::IfThenElseZero(
        s.cone,
        hn::Max(band_cover_lanes(seam_distance_lanes(hn::Mul(hn::Add(u, across), inv_pitch), pitch), seam_width, frame[0], frame[1]),
                band_cover_lanes(seam_distance_lanes(hn::Mul(hn::Sub(u, across), inv_pitch), pitch), seam_width, frame[0], frame[1])));
  }
  const VF seam_shade = hn::Sub(one, hn::Mul(hn::Set(d, kLitterConeSeam), seam));
  const VF shade = hn::Sub(one, hn::Mul(hn::Set(d, kLitterShadow), shadow));
  for (int k = 0; k < 3; ++k) {
    const VF dark = hn::IfThenElse(
        s.fresh, hn::Set(d, kGroundFallenOrange[k]),
        per_kind(s, kLitterLeafDark[k], kLitterBladeDark[k], kLitterNeedleDark[k], kLitterTwigDark[k], look.dark[k]));
    const VF light = hn::IfThenElse(
        s.fresh, hn::Set(d, kGroundFallenYellow[k]),
        per_kind(s, kLitterLeafLight[k], kLitterBladeLight[k], kLitterNeedleLight[k], kLitterTwigLight[k], look.light[k]));
    c[k] = mix_lanes(hn::Mul(c[k], shade), hn::Mul(hn::Mul(mix_lanes(dark, light, s.hue), rib_shade), seam_shade), cover);
  }
  VF side = hn::CopySign(hn::IfThenElseZero(s.leaf, hn::Set(d, kLitterCurl)), across);
  if (any_cone) {
    const VF flank = hn::Min(hn::Max(hn::Div(across, hn::Max(half_width, hn::Set(d, 1e-6f))), hn::Set(d, -1.0f)), one);
    side = hn::IfThenElse(s.cone, hn::Mul(hn::Set(d, kLitterConeRound), flank), side);
  }
  sx = mix_lanes(sx, hn::Sub(hn::Mul(ux, s.tilt), hn::Mul(uy, side)), cover);
  sy = mix_lanes(sy, hn::Add(hn::Mul(uy, s.tilt), hn::Mul(ux, side)), cover);
}

/// floor_litter.cpp's each_cell_around on lanes: lay(h1, h2, rx, ry) for the cells around each lane's point.
template <class Lay>
inline void each_cell_around_lanes(VF x, VF y, float cell, uint32_t z, uint32_t salt, Lay lay) {
  const DF d;
  const DU du;
  const VF gx = hn::Mul(x, hn::Set(d, 1.0f / cell)), gy = hn::Mul(y, hn::Set(d, 1.0f / cell));
  const VF fx = hn::Floor(gx), fy = hn::Floor(gy);
  const VU ix = hn::BitCast(du, hn::ConvertTo(DI(), fx)), iy = hn::BitCast(du, hn::ConvertTo(DI(), fy));
  const VF size = hn::Set(d, cell);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const VU cx = hn::Add(ix, hn::Set(du, uint32_t(dx))), cy = hn::Add(iy, hn::Set(du, uint32_t(dy)));
      const VU mixed = hn::Xor(hn::Mul(cx, hn::Set(du, 0x8da6b343u)), hn::Mul(cy, hn::Set(du, 0xd8163841u)));
      const VU h1 = lattice_hash_of_mix(hn::Xor(mixed, hn::Set(du, z * 0xcb1ab31fu)), salt);
      const VU h2 = lattice_hash_of_mix(hn::Xor(mixed, hn::Set(du, (z + 1u) * 0xcb1ab31fu)), salt);
      const VF rx = hn::Mul(hn::Sub(hn::Sub(gx, hn::Add(fx, hn::Set(d, float(dx)))), byte_value_lanes(h1, 0)), size);
      const VF ry = hn::Mul(hn::Sub(hn::Sub(gy, hn::Add(fy, hn::Set(d, float(dy)))), byte_value_lanes(h1, 8)), size);
      lay(h1, h2, rx, ry);
    }
}

/// The lanes' colours, slope and the filter frame {half_f, inv_f} for a footprint clamped to [1e-4, widest].
struct SpriteCanvas {
  VF c[3], sx, sy;
  VF frame[2];
  SpriteCanvas(const VF* colour, VF slope_x, VF slope_y, VF footprint, float widest)
      : c{colour[0], colour[1], colour[2]}, sx(slope_x), sy(slope_y) {
    const DF d;
    const VF fp = hn::Min(hn::Max(footprint, hn::Set(d, 1e-4f)), hn::Set(d, widest));
    frame[0] = hn::Mul(hn::Set(d, 0.5f), fp);
    frame[1] = hn::Div(hn::Set(d, 1.0f), fp);
  }
  /// Writes the canvas back into the lanes `drawn` of c, sx, sy.
  void keep(hn::Mask<DF> drawn, VF* colour, VF& slope_x, VF& slope_y) const {
    for (int k = 0; k < 3; ++k) colour[k] = hn::IfThenElse(drawn, c[k], colour[k]);
    slope_x = hn::IfThenElse(drawn, sx, slope_x);
    slope_y = hn::IfThenElse(drawn, sy, slope_y);
  }
};

/// litter_sprites on lanes: the sprites over the lanes' colours `c` and relief slope (sx, sy) at
/// points (x, y); lanes whose weight is not above 0 keep theirs unchanged, as the scalar function does.
inline void litter_sprites_lanes(VF x, VF y, VF footprint, const LitterMixLanes& m, VF* c, VF& sx, VF& sy) {
  const DF d;
  const auto drawn = hn::Gt(m.weight, hn::Zero(d));
  if (hn::AllFalse(d, drawn)) return;
  SpriteCanvas canvas(c, sx, sy, footprint, kLitterWidestFilter);
  const LayerLook look{kLitterConePitch, kLitterConeDark, kLitterConeLight, kLitterShadowWidth, kLitterReach};
  for (int layer = 0; layer < kLitterLayers; ++layer)
    each_cell_around_lanes(x, y, kLitterCell, 2u * uint32_t(layer), kGroundLitterSalt, [&](VU h1, VU h2, VF rx, VF ry) {
      lay_sprite_lanes(sprite_lanes(h1, h2, m), h1, rx, ry, canvas.frame, m.weight, look, canvas.c, canvas.sx, canvas.sy);
    });
  canvas.keep(drawn, c, sx, sy);
}

/// floor_litter.cpp's spruce_cone_of on lanes.
inline SpriteLanes spruce_cone_lanes(VU h1, VU h2, VF density) {
  const DF d;
  const VF one = hn::Set(d, 1.0f), two = hn::Set(d, 2.0f);
  const VF size = byte_value_lanes(h2, 0), pick = byte_value_lanes(h2, 24);
  SpriteLanes s;
  s.hue = byte_value_lanes(h2, 8);
  const auto none = hn::FirstN(d, 0);
  s.cone = s.taper = hn::FirstN(d, hn::Lanes(d));
  s.leaf = s.blade = s.needle = s.fresh = none;
  s.keep = hn::IfThenElseZero(hn::Lt(pick, hn::Mul(hn::Set(d, kSpruceConeShare), density)), one);
  s.tilt = hn::Mul(hn::Sub(hn::Mul(byte_value_lanes(hn::Xor(h1, h2), 4), two), one), hn::Set(d, kLitterTilt));
  s.half_length = hn::Add(hn::Set(d, kSpruceConeHalf[0]), hn::Mul(hn::Set(d, kSpruceConeHalf[1]), size));
  s.middle = hn::Mul(hn::Set(d, kSpruceConeWidth), s.half_length);
  return s;
}

/// spruce_cones on lanes (density and weight per lane); lanes whose weight or density is not above 0 keep
/// their colour and slope, as the scalar function does.
inline void spruce_cones_lanes(VF x, VF y, VF footprint, VF density, VF weight, VF* c, VF& sx, VF& sy) {
  const DF d;
  const auto drawn = hn::And(hn::Gt(weight, hn::Zero(d)), hn::Gt(density, hn::Zero(d)));
  if (hn::AllFalse(d, drawn)) return;
  SpriteCanvas canvas(c, sx, sy, footprint, kSpruceConeWidestFilter);
  const LayerLook look{kSpruceConePitch, kSpruceConeDark, kSpruceConeLight, kSpruceConeShadowWidth, kSpruceConeReach};
  each_cell_around_lanes(x, y, kSpruceConeCell, 0u, kGroundConeSalt, [&](VU h1, VU h2, VF rx, VF ry) {
    lay_sprite_lanes(spruce_cone_lanes(h1, h2, density), h1, rx, ry, canvas.frame, weight, look, canvas.c, canvas.sx,
                     canvas.sy);
  });
  canvas.keep(drawn, c, sx, sy);
}

}  // namespace silva::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // SILVA_RENDER_FLOOR_LITTER_LANES_INL_HPP
