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

/// The constant of each sprite kind on lanes: `leaf`, `needle` or `twig` where the masks say.
template <class M>
VF per_kind(M leaf, M needle, float leaf_value, float needle_value, float twig_value) {
  const DF d;
  return hn::IfThenElse(leaf, hn::Set(d, leaf_value), hn::IfThenElse(needle, hn::Set(d, needle_value), hn::Set(d, twig_value)));
}

/// One cell's sprite over the lanes' colours `c` and slope (sx, sy): floor_litter.cpp's loop body.
/// `g` and `f` are the points in grid units and their cells' floors; `frame` = {half_f, inv_f}.
inline void litter_cell_lanes(VU h1, VU h2, const VF* g, const VF* f, int dx, int dy, const VF* frame, VF needles,
                              VF fresh, VF weight, VF* c, VF& sx, VF& sy) {
  const DF d;
  const VF one = hn::Set(d, 1.0f), two = hn::Set(d, 2.0f);
  const VF size = byte_value_lanes(h2, 0), hue = byte_value_lanes(h2, 8), kind = byte_value_lanes(h2, 16);
  const VF pick = byte_value_lanes(h2, 24);
  const auto twig = hn::Ge(kind, hn::Set(d, 1.0f - kLitterTwigShare));
  const auto needle = hn::AndNot(twig, hn::Lt(kind, needles));
  const auto leaf = hn::Not(hn::Or(twig, needle));
  const VF keep = hn::IfThenElseZero(hn::Lt(pick, hn::Set(d, kLitterDensity)), one);
  const VF tilt = hn::Mul(hn::Sub(hn::Mul(byte_value_lanes(hn::Xor(h1, h2), 4), two), one), hn::Set(d, kLitterTilt));
  const VF half_length = hn::Add(per_kind(leaf, needle, kLitterLeafHalf[0], kLitterNeedleHalf[0], kLitterTwigHalf[0]),
                                 hn::Mul(per_kind(leaf, needle, kLitterLeafHalf[1], kLitterNeedleHalf[1], kLitterTwigHalf[1]), size));
  const VF twig_width = hn::Add(hn::Set(d, kLitterTwigHalfWidth[0]), hn::Mul(hn::Set(d, kLitterTwigHalfWidth[1]), hue));
  const VF width = hn::Add(hn::Set(d, kLitterLeafWidth[0]), hn::Mul(hn::Set(d, kLitterLeafWidth[1]), byte_value_lanes(hn::Xor(h1, h2), 12)));
  const VF middle = hn::IfThenElse(leaf, hn::Mul(width, half_length),
                                   hn::IfThenElse(needle, hn::Set(d, kLitterNeedleHalfWidth), twig_width));
  const auto fresh_leaf = hn::And(leaf, hn::Lt(pick, hn::Mul(hn::Set(d, kLitterDensity), fresh)));
  const VF cell = hn::Set(d, kLitterCell);
  const VF rx = hn::Mul(hn::Sub(hn::Sub(g[0], hn::Add(f[0], hn::Set(d, float(dx)))), byte_value_lanes(h1, 0)), cell);
  const VF ry = hn::Mul(hn::Sub(hn::Sub(g[1], hn::Add(f[1], hn::Set(d, float(dy)))), byte_value_lanes(h1, 8)), cell);
  const VF reach = hn::Set(d, kLitterShadowWidth + 1e-4f);  // floor_litter.cpp's kLitterReach
  const VF reach_u = hn::Add(hn::Add(half_length, reach), frame[0]), reach_v = hn::Add(hn::Add(middle, reach), frame[0]);
  const auto near = hn::And(hn::Gt(keep, hn::Zero(d)), hn::Lt(hn::Add(hn::Mul(rx, rx), hn::Mul(ry, ry)),
                                                             hn::Add(hn::Mul(reach_u, reach_u), hn::Mul(reach_v, reach_v))));
  if (hn::AllFalse(d, near)) return;  // it reaches none of the points (the lanes it misses gain nothing from it)
  const VF ax = hn::Sub(hn::Mul(byte_value_lanes(h1, 16), two), one), ay = hn::Sub(hn::Mul(byte_value_lanes(h1, 24), two), one);
  const VF len = hn::Sqrt(hn::Add(hn::Add(hn::Mul(ax, ax), hn::Mul(ay, ay)), hn::Set(d, 1e-8f)));
  const VF ux = hn::Div(ax, len), uy = hn::Div(ay, len);
  const VF u = hn::Add(hn::Mul(rx, ux), hn::Mul(ry, uy)), across = hn::Sub(hn::Mul(ry, ux), hn::Mul(rx, uy));
  const VF v = hn::Abs(across);
  const VF t = hn::Div(u, half_length);
  const VF half_width = hn::IfThenElse(leaf, hn::Mul(middle, hn::Sub(one, hn::Mul(t, t))), middle);
  const VF presence = hn::Mul(keep, weight);
  const VF cover = hn::Mul(hn::Mul(band_cover_lanes(v, half_width, frame[0], frame[1]),
                                   band_cover_lanes(u, half_length, frame[0], frame[1])), presence);
  const VF rim = hn::Set(d, kLitterShadowWidth);
  const VF shadow = hn::Mul(hn::Mul(band_cover_lanes(v, hn::Add(half_width, rim), frame[0], frame[1]),
                                    band_cover_lanes(u, hn::Add(half_length, rim), frame[0], frame[1])), presence);
  const VF rib = hn::IfThenElseZero(leaf, hn::Mul(band_cover_lanes(v, hn::Set(d, kLitterRibHalfWidth), frame[0], frame[1]),
                                                  band_cover_lanes(u, hn::Mul(hn::Set(d, 0.9f), half_length), frame[0], frame[1])));
  const VF rib_shade = hn::Sub(one, hn::Mul(hn::Set(d, kLitterRib), rib));
  const VF shade = hn::Sub(one, hn::Mul(hn::Set(d, kLitterShadow), shadow));
  for (int k = 0; k < 3; ++k) {
    const VF dark = hn::IfThenElse(fresh_leaf, hn::Set(d, kGroundFallenOrange[k]),
                                   per_kind(leaf, needle, kLitterLeafDark[k], kLitterNeedleDark[k], kLitterTwigDark[k]));
    const VF light = hn::IfThenElse(fresh_leaf, hn::Set(d, kGroundFallenYellow[k]),
                                    per_kind(leaf, needle, kLitterLeafLight[k], kLitterNeedleLight[k], kLitterTwigLight[k]));
    c[k] = mix_lanes(hn::Mul(c[k], shade), hn::Mul(mix_lanes(dark, light, hue), rib_shade), cover);
  }
  const VF side = hn::CopySign(hn::IfThenElseZero(leaf, hn::Set(d, kLitterCurl)), across);
  sx = mix_lanes(sx, hn::Sub(hn::Mul(ux, tilt), hn::Mul(uy, side)), cover);
  sy = mix_lanes(sy, hn::Add(hn::Mul(uy, tilt), hn::Mul(ux, side)), cover);
}

/// litter_sprites on lanes: the sprites over the lanes' colours `c` and relief slope (sx, sy) at
/// points (x, y); lanes whose `weight` is not above 0 keep theirs unchanged, as the scalar function does.
inline void litter_sprites_lanes(VF x, VF y, VF footprint, VF needles, VF fresh, VF weight, VF* c, VF& sx, VF& sy) {
  const DF d;
  const DU du;
  const auto drawn = hn::Gt(weight, hn::Zero(d));
  if (hn::AllFalse(d, drawn)) return;
  const VF fp = hn::Min(hn::Max(footprint, hn::Set(d, 1e-4f)), hn::Set(d, kLitterWidestFilter));
  const VF frame[2] = {hn::Mul(hn::Set(d, 0.5f), fp), hn::Div(hn::Set(d, 1.0f), fp)};
  const VF g[2] = {hn::Mul(x, hn::Set(d, 1.0f / kLitterCell)), hn::Mul(y, hn::Set(d, 1.0f / kLitterCell))};
  const VF f[2] = {hn::Floor(g[0]), hn::Floor(g[1])};
  const VU ix = hn::BitCast(du, hn::ConvertTo(DI(), f[0])), iy = hn::BitCast(du, hn::ConvertTo(DI(), f[1]));
  VF nc[3] = {c[0], c[1], c[2]}, nx = sx, ny = sy;
  for (int layer = 0; layer < kLitterLayers; ++layer)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const VU cx = hn::Add(ix, hn::Set(du, uint32_t(dx))), cy = hn::Add(iy, hn::Set(du, uint32_t(dy)));
        const VU mixed = hn::Xor(hn::Mul(cx, hn::Set(du, 0x8da6b343u)), hn::Mul(cy, hn::Set(du, 0xd8163841u)));
        const uint32_t z = 2u * uint32_t(layer);
        const VU h1 = lattice_hash_of_mix(hn::Xor(mixed, hn::Set(du, z * 0xcb1ab31fu)), kGroundLitterSalt);
        const VU h2 = lattice_hash_of_mix(hn::Xor(mixed, hn::Set(du, (z + 1u) * 0xcb1ab31fu)), kGroundLitterSalt);
        litter_cell_lanes(h1, h2, g, f, dx, dy, frame, needles, fresh, weight, nc, nx, ny);
      }
  for (int k = 0; k < 3; ++k) c[k] = hn::IfThenElse(drawn, nc[k], c[k]);
  sx = hn::IfThenElse(drawn, nx, sx);
  sy = hn::IfThenElse(drawn, ny, sy);
}

}  // namespace silva::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // SILVA_RENDER_FLOOR_LITTER_LANES_INL_HPP
