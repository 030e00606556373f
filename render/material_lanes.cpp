// The per-target kernels of ground_albedo_row and foliage_albedo_row (render/materials.hpp), compiled
// once per Highway target (foreach_target) and chosen at run time. Value noise, fBm and the
// forest-floor blend run one point per float lane with the scalar functions' operations
// (shading_noise.hpp) in the same order, no MulAdd, so every target gives the same bits.
#include <algorithm>

#include "render/materials.hpp"
#include "core/value_noise.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/material_lanes.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"
#include "render/shading_noise_lanes-inl.hpp"
#include "render/floor_litter_lanes-inl.hpp"

HWY_BEFORE_NAMESPACE();
namespace silva::render::HWY_NAMESPACE {

/// The moss's texture near the camera (materials.hpp): its brightness factor on kGroundMoss, 1 where
/// the moss or its detail is absent, and the cushions' relief gradient added to (sx, sy).
VF moss_cushions_lanes(VF px, VF py, VF footprint, VF moss, VF& sx, VF& sy) {
  const DF d;
  const VF shown = hn::Mul(hn::Sub(hn::Set(d, 1.0f), smoothstep_lanes(kMossDetailNear, kMossDetailFar, footprint)), moss);
  if (hn::AllTrue(d, hn::Eq(shown, hn::Zero(d)))) return hn::Set(d, 1.0f);
  VF cdx, cdy, tdx, tdy;
  const VF cushion = value_noise2_lanes(hn::Mul(px, hn::Set(d, 40.0f)), hn::Mul(py, hn::Set(d, 40.0f)), kGroundCushionSalt, &cdx, &cdy);
  const VF tips = value_noise2_lanes(hn::Mul(px, hn::Set(d, 110.0f)), hn::Mul(py, hn::Set(d, 110.0f)), kGroundCushionSalt + 1, &tdx, &tdy);
  const VF kc = hn::Set(d, 40.0f * kMossCushionRelief), kt = hn::Set(d, 110.0f * kMossTipRelief);
  sx = hn::Add(sx, hn::Mul(hn::Add(hn::Mul(cdx, kc), hn::Mul(tdx, kt)), shown));
  sy = hn::Add(sy, hn::Mul(hn::Add(hn::Mul(cdy, kc), hn::Mul(tdy, kt)), shown));
  const VF mixed = hn::Add(hn::Mul(cushion, hn::Set(d, 0.7f)), hn::Mul(tips, hn::Set(d, 0.3f)));
  return hn::Add(hn::Set(d, 1.0f), hn::Mul(hn::Mul(hn::Sub(mixed, hn::Set(d, 0.5f)), hn::Set(d, 0.9f)), shown));
}

/// The forest-floor formula of ground_albedo_row (materials.hpp) for one vector of points: colour
/// `c`, relief slope (sx, sy) and bare-soil weight, then the litter sprites (floor_litter.hpp) on top.
void ground_lanes(VF px, VF py, VF nz, VF footprint, const FloorLook& floor, VF* c, VF& sx, VF& sy, VF& soil) {
  const float fallen_leaves = floor.fallen_leaves;
  const DF d;
  const auto scaled = [&](VF v, float k) { return hn::Mul(v, hn::Set(d, k)); };
  const VF one = hn::Set(d, 1.0f);
  const VF flat = smoothstep_lanes(0.6f, 0.9f, nz);
  const VF fine_detail = hn::Sub(one, smoothstep_lanes(0.01f, 0.05f, footprint));
  const VF sprites = hn::Sub(one, smoothstep_lanes(kLitterFadeNear, kLitterFadeFar, footprint));
  const VF blotches = hn::Mul(fine_detail, hn::Sub(one, sprites));
  const VF needles = floor.needle_share >= 0.0f
                         ? hn::Set(d, floor.needle_share)
                         : smoothstep_lanes(0.42f, 0.58f, fbm2_lanes(scaled(px, 0.02f), scaled(py, 0.02f), 2, kGroundStandSalt));
  VF leaf_dx, leaf_dy, speckle_dx, speckle_dy;
  const VF leaf = value_noise2_lanes(scaled(px, 9.0f), scaled(py, 9.0f), kGroundLeafSalt, &leaf_dx, &leaf_dy);
  const VF dry = hn::Mul(hn::Mul(smoothstep_lanes(0.6f, 0.8f, leaf), hn::Sub(one, needles)), blotches);
  const VF grass =
      hn::Mul(scaled(smoothstep_lanes(0.62f, 0.78f, fbm2_lanes(scaled(px, 0.06f), scaled(py, 0.06f), 2, kGroundGrassSalt)), 0.8f), flat);
  const VF moss =
      hn::Mul(scaled(smoothstep_lanes(0.6f, 0.72f, fbm2_lanes(scaled(px, 0.15f), scaled(py, 0.15f), 3, kGroundMossSalt)), 0.85f), flat);
  soil = hn::Max(hn::Sub(one, flat), smoothstep_lanes(0.7f, 0.84f, fbm2_lanes(scaled(px, 0.5f), scaled(py, 0.5f), 3, kGroundSoilSalt)));
  const VF grain = fbm2_lanes(scaled(px, 4.0f), scaled(py, 4.0f), 2, kGroundFineSalt);
  const VF grain_amount = hn::Sub(one, smoothstep_lanes(0.1f, 0.4f, footprint));
  const VF speckle = value_noise2_lanes(scaled(px, 23.0f), scaled(py, 23.0f), kGroundLeafSalt + 1, &speckle_dx, &speckle_dy);
  const VF brightness = hn::Mul(hn::Add(one, hn::Mul(hn::Sub(scaled(grain, 0.6f), hn::Set(d, 0.3f)), grain_amount)),
                                hn::Add(one, hn::Mul(hn::Sub(scaled(speckle, 0.8f), hn::Set(d, 0.4f)), fine_detail)));
  VF fallen = hn::Zero(d), fallen_hue = hn::Zero(d);
  if (fallen_leaves > 0.0f) {  // drifts of fresh leaves over everything but bare soil, thinner under conifers
    const VF drift = smoothstep_lanes(0.25f, 0.55f, fbm2_lanes(scaled(px, 0.4f), scaled(py, 0.4f), 2, kGroundFallenSalt));
    fallen = hn::Mul(scaled(drift, fallen_leaves), hn::Sub(one, scaled(needles, 0.7f)));
    const VF hue_field = fbm2_lanes(scaled(px, 1.5f), scaled(py, 1.5f), 2, kGroundFallenSalt + 8);
    fallen_hue = mix_lanes(hue_field, smoothstep_lanes(0.3f, 0.7f, leaf), fine_detail);
  }
  const float kl = 9.0f * kGroundLeafRelief, ks = 23.0f * kGroundSpeckleRelief;  // relief heights in metres
  const VF blotch_relief = hn::Sub(one, sprites);
  sx = hn::Mul(hn::Add(hn::Mul(scaled(leaf_dx, kl), blotch_relief), scaled(speckle_dx, ks)), fine_detail);
  sy = hn::Mul(hn::Add(hn::Mul(scaled(leaf_dy, kl), blotch_relief), scaled(speckle_dy, ks)), fine_detail);
  const VF moss_tone = moss_cushions_lanes(px, py, footprint, moss, sx, sy);
  for (int k = 0; k < 3; ++k) {
    VF v = mix_lanes(hn::Set(d, kGroundLeafLitter[k]), hn::Set(d, kGroundNeedleLitter[k]), needles);
    v = mix_channel(v, kGroundDryLeaves, k, dry);
    v = mix_channel(v, kGroundGrass, k, grass);
    v = mix_lanes(v, hn::Mul(hn::Set(d, kGroundMoss[k]), moss_tone), moss);
    if (fallen_leaves > 0.0f) {
      const VF fresh = hn::Add(hn::Set(d, kGroundFallenOrange[k]),
                               hn::Mul(fallen_hue, hn::Set(d, kGroundFallenYellow[k] - kGroundFallenOrange[k])));
      v = mix_lanes(v, fresh, fallen);
    }
    v = mix_channel(v, kGroundSoil, k, soil);
    c[k] = hn::Mul(v, brightness);
  }
  const VF litter = hn::Mul(hn::Mul(sprites, hn::Sub(one, scaled(moss, 0.7f))), hn::Sub(one, soil));
  const VF blades = scaled(grass, 1.0f / 0.8f);  // a full grass cover (0.8) grows only blades
  litter_sprites_lanes(px, py, footprint, {blades, needles, fallen, litter}, c, sx, sy);
  if (floor.spruce_cones > 0.0f) {
    const VF cone_weight = hn::Mul(hn::Mul(hn::Sub(one, smoothstep_lanes(kSpruceConeFadeNear, kSpruceConeFadeFar, footprint)),
                                           hn::Sub(one, scaled(moss, 0.7f))),
                                   hn::Sub(one, soil));
    spruce_cones_lanes(px, py, footprint, scaled(needles, floor.spruce_cones), cone_weight, c, sx, sy);
  }
}

/// ground_albedo_row for one target.
void GroundRowImpl(const Vec3f* positions, const Vec3f* normals, const float* footprints, size_t count, Vec3f* out,
                   float* soil_out, Vec2f* slope_out, const FloorLook& floor) {
  if (count == 0) return;  // the arrays may be empty vectors' null data()
  const DF d;
  const size_t N = hn::Lanes(d);
  for (size_t first = 0; first < count; first += N) {
    const size_t lanes = std::min(N, count - first);
    HWY_ALIGN float pin[3 * hn::MaxLanes(d)] = {}, nin[3 * hn::MaxLanes(d)] = {}, res[3 * hn::MaxLanes(d)];
    HWY_ALIGN float fin[hn::MaxLanes(d)] = {};
    std::copy(positions->data() + 3 * first, positions->data() + 3 * (first + lanes), pin);
    std::copy(normals->data() + 3 * first, normals->data() + 3 * (first + lanes), nin);
    std::copy(footprints + first, footprints + first + lanes, fin);
    VF px, py, pz, nx, ny, nz, c[3], sx, sy, soil;
    hn::LoadInterleaved3(d, pin, px, py, pz);
    hn::LoadInterleaved3(d, nin, nx, ny, nz);
    ground_lanes(px, py, nz, hn::Load(d, fin), floor, c, sx, sy, soil);
    hn::StoreInterleaved3(c[0], c[1], c[2], d, res);
    std::copy(res, res + 3 * lanes, out->data() + 3 * first);
    if (slope_out) {
      HWY_ALIGN float xs[hn::MaxLanes(d)], ys[hn::MaxLanes(d)];
      hn::Store(sx, d, xs);
      hn::Store(sy, d, ys);
      for (size_t k = 0; k < lanes; ++k) slope_out[first + k] = Vec2f(xs[k], ys[k]);
    }
    if (soil_out) {
      HWY_ALIGN float w[hn::MaxLanes(d)];
      hn::Store(soil, d, w);
      std::copy(w, w + lanes, soil_out + first);
    }
  }
}

/// foliage_albedo_row for one target: materials.cpp's variation_tint and foliage mottle on lanes.
void FoliageRowImpl(const Vec3f* points, const uint32_t* variations, const Vec3f* bases, const float* leaf_shades,
                    size_t count, Vec3f* out) {
  const DF d;
  const DU du;
  const size_t N = hn::Lanes(d);
  const VF scale = hn::Set(d, kFoliageMottleScale), one = hn::Set(d, 1.0f);
  for (size_t first = 0; first < count; first += N) {
    const size_t lanes = std::min(N, count - first);
    HWY_ALIGN float pin[3 * hn::MaxLanes(d)] = {}, bin[3 * hn::MaxLanes(d)] = {}, res[3 * hn::MaxLanes(d)];
    HWY_ALIGN uint32_t vin[hn::MaxLanes(d)] = {};
    HWY_ALIGN float lin[hn::MaxLanes(d)] = {};
    std::copy(points->data() + 3 * first, points->data() + 3 * (first + lanes), pin);
    std::copy(bases->data() + 3 * first, bases->data() + 3 * (first + lanes), bin);
    std::copy(variations + first, variations + first + lanes, vin);
    std::copy(leaf_shades + first, leaf_shades + first + lanes, lin);
    VF px, py, pz, br, bg, bb;
    hn::LoadInterleaved3(d, pin, px, py, pz);
    hn::LoadInterleaved3(d, bin, br, bg, bb);
    const VU variation = hn::Load(du, vin);
    const VF bright = hn::Add(hn::Set(d, 0.8f), hn::Mul(hn::Set(d, 0.4f), lattice_value_lanes(variation, 17, 3, kFoliage)));
    const VF yellow = hn::Mul(hn::Set(d, 0.25f), lattice_value_lanes(variation, 5, 11, kFoliage));
    const VF mottle = value_noise3_lanes(hn::Mul(px, scale), hn::Mul(py, scale), hn::Mul(pz, scale), kFoliageMottleSalt);
    const VF shade = hn::Add(hn::Set(d, 0.8f), hn::Mul(hn::Set(d, 0.4f), mottle));
    const VF leaf = hn::Load(d, lin);
    const VF tr = hn::Mul(bright, hn::Add(one, yellow));
    const VF tg = hn::Mul(bright, hn::Add(one, hn::Mul(hn::Set(d, 0.4f), yellow)));
    const VF tb = hn::Mul(bright, hn::Sub(one, hn::Mul(hn::Set(d, 0.5f), yellow)));
    hn::StoreInterleaved3(hn::Mul(hn::Mul(hn::Mul(br, tr), shade), leaf), hn::Mul(hn::Mul(hn::Mul(bg, tg), shade), leaf),
                          hn::Mul(hn::Mul(hn::Mul(bb, tb), shade), leaf), d, res);
    std::copy(res, res + 3 * lanes, out->data() + 3 * first);
  }
}

/// The target this copy of the kernel was compiled for.
int64_t GroundTargetImpl() { return HWY_TARGET; }

}  // namespace silva::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace silva::render {

HWY_EXPORT(GroundRowImpl);
HWY_EXPORT(GroundTargetImpl);
HWY_EXPORT(FoliageRowImpl);

void foliage_albedo_row(const Vec3f* points, const uint32_t* variations, const Vec3f* bases, const float* leaf_shades,
                        size_t count, Vec3f* out) {
  HWY_DYNAMIC_DISPATCH(FoliageRowImpl)(points, variations, bases, leaf_shades, count, out);
}

void ground_albedo_row(const Vec3f* positions, const Vec3f* normals, const float* footprints, size_t count,
                       Vec3f* out, float* soil, Vec2f* slope, const FloorLook& floor) {
  if (count > 0) HWY_DYNAMIC_DISPATCH(GroundRowImpl)(positions, normals, footprints, count, out, soil, slope, floor);
}

int64_t ground_simd_target() { return HWY_DYNAMIC_DISPATCH(GroundTargetImpl)(); }

}  // namespace silva::render
#endif  // HWY_ONCE
