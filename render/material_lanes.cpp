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

HWY_BEFORE_NAMESPACE();
namespace silva::render::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;    ///< One point per lane.
using DU = hn::RebindToUnsigned<DF>;  ///< Lattice hashes.
using DI = hn::RebindToSigned<DF>;    ///< Lattice indices.
using VF = hn::Vec<DF>;               ///< Float lanes.
using VU = hn::Vec<DU>;               ///< Hash lanes.

/// smooth_weight on lanes: t * t * (3 - 2 t).
VF smooth_weight_lanes(VF t) {
  const DF d;
  return hn::Mul(hn::Mul(t, t), hn::Sub(hn::Set(d, 3.0f), hn::Mul(hn::Set(d, 2.0f), t)));
}

/// mix on lanes: a + (b - a) t.
VF mix_lanes(VF a, VF b, VF t) { return hn::Add(a, hn::Mul(hn::Sub(b, a), t)); }

/// lattice_value(lattice_hash(...)) on lanes from the hash's mix of the lattice indices `h`.
VF lattice_value_of_mix(VU h, uint32_t salt) {
  const DU du;
  const DF df;
  h = hn::Xor(h, hn::Set(du, salt * 0x9e3779b9u));
  h = hn::Xor(h, hn::ShiftRight<16>(h));
  h = hn::Mul(h, hn::Set(du, 0x85ebca6bu));
  h = hn::Xor(h, hn::ShiftRight<13>(h));
  h = hn::Mul(h, hn::Set(du, 0xc2b2ae35u));
  h = hn::Xor(h, hn::ShiftRight<16>(h));
  const auto top = hn::BitCast(DI(), hn::ShiftRight<8>(h));  // < 2^24: exact as float
  return hn::Mul(hn::ConvertTo(df, top), hn::Set(df, 1.0f / 16777216.0f));
}

/// lattice_value(lattice_hash(x, y, 0, salt)) on lanes (x, y are the lattice indices as u32).
VF lattice_value_lanes(VU x, VU y, uint32_t salt) {
  const DU du;
  return lattice_value_of_mix(hn::Xor(hn::Mul(x, hn::Set(du, 0x8da6b343u)), hn::Mul(y, hn::Set(du, 0xd8163841u))), salt);
}

/// lattice_value(lattice_hash(x, y, z, salt)) on lanes.
VF lattice_value_lanes(VU x, VU y, VU z, uint32_t salt) {
  const DU du;
  const VU xy = hn::Xor(hn::Mul(x, hn::Set(du, 0x8da6b343u)), hn::Mul(y, hn::Set(du, 0xd8163841u)));
  return lattice_value_of_mix(hn::Xor(xy, hn::Mul(z, hn::Set(du, 0xcb1ab31fu))), salt);
}

/// Derivative of smooth_weight on lanes: 6 t (1 - t).
VF smooth_slope_lanes(VF t) {
  const DF d;
  return hn::Mul(hn::Mul(hn::Set(d, 6.0f), t), hn::Sub(hn::Set(d, 1.0f), t));
}

/// value_noise2 on lanes; with `dx`, `dy` also its gradient (per unit of x and y).
VF value_noise2_lanes(VF x, VF y, uint32_t salt, VF* dx = nullptr, VF* dy = nullptr) {
  const DU du;
  const VF fx = hn::Floor(x), fy = hn::Floor(y);
  const VU ix = hn::BitCast(du, hn::ConvertTo(DI(), fx)), iy = hn::BitCast(du, hn::ConvertTo(DI(), fy));
  const VF wx = smooth_weight_lanes(hn::Sub(x, fx)), wy = smooth_weight_lanes(hn::Sub(y, fy));
  const VU one = hn::Set(du, 1u);
  const VF v00 = lattice_value_lanes(ix, iy, salt), v10 = lattice_value_lanes(hn::Add(ix, one), iy, salt);
  const VF v01 = lattice_value_lanes(ix, hn::Add(iy, one), salt);
  const VF v11 = lattice_value_lanes(hn::Add(ix, one), hn::Add(iy, one), salt);
  const VF a = mix_lanes(v00, v10, wx), b = mix_lanes(v01, v11, wx);
  if (dx) {
    *dx = hn::Mul(mix_lanes(hn::Sub(v10, v00), hn::Sub(v11, v01), wy), smooth_slope_lanes(hn::Sub(x, fx)));
    *dy = hn::Mul(hn::Sub(b, a), smooth_slope_lanes(hn::Sub(y, fy)));
  }
  return mix_lanes(a, b, wy);
}

/// value_noise3 on lanes.
VF value_noise3_lanes(VF x, VF y, VF z, uint32_t salt) {
  const DU du;
  const VF fx = hn::Floor(x), fy = hn::Floor(y), fz = hn::Floor(z);
  const VU ix = hn::BitCast(du, hn::ConvertTo(DI(), fx)), iy = hn::BitCast(du, hn::ConvertTo(DI(), fy));
  const VU iz = hn::BitCast(du, hn::ConvertTo(DI(), fz));
  const VF wx = smooth_weight_lanes(hn::Sub(x, fx)), wy = smooth_weight_lanes(hn::Sub(y, fy));
  const VF wz = smooth_weight_lanes(hn::Sub(z, fz));
  const VU one = hn::Set(du, 1u), ix1 = hn::Add(ix, one), iy1 = hn::Add(iy, one);
  VF layer[2];
  for (uint32_t k = 0; k < 2; ++k) {
    const VU zk = hn::Add(iz, hn::Set(du, k));
    const VF v00 = lattice_value_lanes(ix, iy, zk, salt), v10 = lattice_value_lanes(ix1, iy, zk, salt);
    const VF v01 = lattice_value_lanes(ix, iy1, zk, salt), v11 = lattice_value_lanes(ix1, iy1, zk, salt);
    layer[k] = mix_lanes(mix_lanes(v00, v10, wx), mix_lanes(v01, v11, wx), wy);
  }
  return mix_lanes(layer[0], layer[1], wz);
}

/// fbm2 on lanes.
VF fbm2_lanes(VF x, VF y, int octaves, uint32_t salt) {
  const DF d;
  VF sum = hn::Zero(d);
  float amp = 1.0f, norm = 0.0f;
  for (int o = 0; o < octaves; ++o) {
    sum = hn::Add(sum, hn::Mul(hn::Set(d, amp), value_noise2_lanes(x, y, salt + uint32_t(o))));
    norm += amp;
    amp *= 0.5f;
    x = hn::Mul(x, hn::Set(d, 2.0f));
    y = hn::Mul(y, hn::Set(d, 2.0f));
  }
  return hn::Div(sum, hn::Set(d, norm));
}

/// materials.cpp's smoothstep on lanes: smooth_weight(clamp((x - e0) / (e1 - e0), 0, 1)).
VF smoothstep_lanes(float e0, float e1, VF x) {
  const DF d;
  const VF t = hn::Div(hn::Sub(x, hn::Set(d, e0)), hn::Set(d, e1 - e0));
  return smooth_weight_lanes(hn::Min(hn::Max(t, hn::Zero(d)), hn::Set(d, 1.0f)));
}

/// mix of a three-channel colour constant towards another, per channel k.
VF mix_channel(VF c, const float* to, int k, VF t) { return mix_lanes(c, hn::Set(DF(), to[k]), t); }

/// ground_albedo_row for one target.
void GroundRowImpl(const Vec3f* positions, const Vec3f* normals, const float* footprints, size_t count, Vec3f* out,
                   float* soil_out, Vec2f* slope_out, float fallen_leaves) {
  if (count == 0) return;  // the arrays may be empty vectors' null data()
  const DF d;
  const size_t N = hn::Lanes(d);
  const float* p = positions->data();
  const float* n = normals->data();
  float* o = out->data();
  const auto scaled = [&](VF v, float k) { return hn::Mul(v, hn::Set(d, k)); };
  const VF one = hn::Set(d, 1.0f);
  for (size_t first = 0; first < count; first += N) {
    const size_t lanes = std::min(N, count - first);
    HWY_ALIGN float pin[3 * hn::MaxLanes(d)] = {}, nin[3 * hn::MaxLanes(d)] = {}, res[3 * hn::MaxLanes(d)];
    HWY_ALIGN float fin[hn::MaxLanes(d)] = {};
    std::copy(p + 3 * first, p + 3 * (first + lanes), pin);
    std::copy(n + 3 * first, n + 3 * (first + lanes), nin);
    std::copy(footprints + first, footprints + first + lanes, fin);
    VF px, py, pz, nx, ny, nz;
    hn::LoadInterleaved3(d, pin, px, py, pz);
    hn::LoadInterleaved3(d, nin, nx, ny, nz);
    const VF footprint = hn::Load(d, fin);
    const VF flat = smoothstep_lanes(0.6f, 0.9f, nz);
    const VF fine_detail = hn::Sub(one, smoothstep_lanes(0.01f, 0.05f, footprint));
    const VF needles = smoothstep_lanes(0.42f, 0.58f, fbm2_lanes(scaled(px, 0.02f), scaled(py, 0.02f), 2, kGroundStandSalt));
    VF leaf_dx, leaf_dy, speckle_dx, speckle_dy;
    const VF leaf = value_noise2_lanes(scaled(px, 9.0f), scaled(py, 9.0f), kGroundLeafSalt, &leaf_dx, &leaf_dy);
    const VF dry = hn::Mul(hn::Mul(smoothstep_lanes(0.6f, 0.8f, leaf), hn::Sub(one, needles)), fine_detail);
    const VF grass =
        hn::Mul(scaled(smoothstep_lanes(0.62f, 0.78f, fbm2_lanes(scaled(px, 0.06f), scaled(py, 0.06f), 2, kGroundGrassSalt)), 0.8f), flat);
    const VF moss =
        hn::Mul(scaled(smoothstep_lanes(0.6f, 0.72f, fbm2_lanes(scaled(px, 0.15f), scaled(py, 0.15f), 3, kGroundMossSalt)), 0.85f), flat);
    const VF soil = hn::Max(hn::Sub(one, flat), smoothstep_lanes(0.7f, 0.84f, fbm2_lanes(scaled(px, 0.5f),
                                                                                         scaled(py, 0.5f), 3, kGroundSoilSalt)));
    const VF grain = fbm2_lanes(scaled(px, 4.0f), scaled(py, 4.0f), 2, kGroundFineSalt);
    const VF grain_amount = hn::Sub(one, smoothstep_lanes(0.1f, 0.4f, footprint));
    const VF speckle =
        value_noise2_lanes(scaled(px, 23.0f), scaled(py, 23.0f), kGroundLeafSalt + 1, &speckle_dx, &speckle_dy);
    const VF brightness =
        hn::Mul(hn::Add(one, hn::Mul(hn::Sub(scaled(grain, 0.6f), hn::Set(d, 0.3f)), grain_amount)),
                hn::Add(one, hn::Mul(hn::Sub(scaled(speckle, 0.8f), hn::Set(d, 0.4f)), fine_detail)));
    VF fallen = hn::Zero(d), fallen_hue = hn::Zero(d), fallen_orange[3], fallen_yellow[3];
    if (fallen_leaves > 0.0f) {  // drifts of fresh leaves over everything but bare soil, thinner under conifers
      const VF drift = smoothstep_lanes(0.25f, 0.55f, fbm2_lanes(scaled(px, 0.4f), scaled(py, 0.4f), 2, kGroundFallenSalt));
      fallen = hn::Mul(scaled(drift, fallen_leaves), hn::Sub(one, scaled(needles, 0.7f)));
      const VF hue_field = fbm2_lanes(scaled(px, 1.5f), scaled(py, 1.5f), 2, kGroundFallenSalt + 8);
      fallen_hue = mix_lanes(hue_field, smoothstep_lanes(0.3f, 0.7f, leaf), fine_detail);
      for (int k = 0; k < 3; ++k) {
        fallen_orange[k] = hn::Set(d, kGroundFallenOrange[k]);
        fallen_yellow[k] = hn::Set(d, kGroundFallenYellow[k] - kGroundFallenOrange[k]);
      }
    }
    VF c[3];
    for (int k = 0; k < 3; ++k) {
      VF v = mix_lanes(hn::Set(d, kGroundLeafLitter[k]), hn::Set(d, kGroundNeedleLitter[k]), needles);
      v = mix_channel(v, kGroundDryLeaves, k, dry);
      v = mix_channel(v, kGroundGrass, k, grass);
      v = mix_channel(v, kGroundMoss, k, moss);
      if (fallen_leaves > 0.0f) v = mix_lanes(v, hn::Add(fallen_orange[k], hn::Mul(fallen_hue, fallen_yellow[k])), fallen);
      v = mix_channel(v, kGroundSoil, k, soil);
      c[k] = hn::Mul(v, brightness);
    }
    hn::StoreInterleaved3(c[0], c[1], c[2], d, res);
    std::copy(res, res + 3 * lanes, o + 3 * first);
    if (slope_out) {  // relief height kGroundLeafRelief leaf + kGroundSpeckleRelief speckle, in metres
      const float kl = 9.0f * kGroundLeafRelief, ks = 23.0f * kGroundSpeckleRelief;
      const VF sx = hn::Mul(hn::Add(scaled(leaf_dx, kl), scaled(speckle_dx, ks)), fine_detail);
      const VF sy = hn::Mul(hn::Add(scaled(leaf_dy, kl), scaled(speckle_dy, ks)), fine_detail);
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

/// lattice_value(lattice_hash(x, y, z, salt)) on lanes of x with y and z the same on every lane.
VF lattice_value_lanes(VU x, uint32_t y, uint32_t z, uint32_t salt) {
  const DU du;
  return lattice_value_of_mix(hn::Xor(hn::Mul(x, hn::Set(du, 0x8da6b343u)), hn::Set(du, y * 0xd8163841u ^ z * 0xcb1ab31fu)),
                              salt);
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
                       Vec3f* out, float* soil, Vec2f* slope, float fallen_leaves) {
  if (count > 0)
    HWY_DYNAMIC_DISPATCH(GroundRowImpl)(positions, normals, footprints, count, out, soil, slope, fallen_leaves);
}

int64_t ground_simd_target() { return HWY_DYNAMIC_DISPATCH(GroundTargetImpl)(); }

}  // namespace silva::render
#endif  // HWY_ONCE
