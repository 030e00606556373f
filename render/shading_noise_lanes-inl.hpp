// Value noise, fBm and smoothstep on Highway lanes: core/value_noise.hpp's scalar functions with
// their operations in the same order and no MulAdd, so every target gives the same bits. Included
// once per target (Highway's -inl convention) by the kernels that shade procedural materials.
#if defined(SILVA_RENDER_SHADING_NOISE_LANES_INL_HPP) == defined(HWY_TARGET_TOGGLE)
#ifdef SILVA_RENDER_SHADING_NOISE_LANES_INL_HPP
#undef SILVA_RENDER_SHADING_NOISE_LANES_INL_HPP
#else
#define SILVA_RENDER_SHADING_NOISE_LANES_INL_HPP
#endif

#include <cstdint>

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
inline VF smooth_weight_lanes(VF t) {
  const DF d;
  return hn::Mul(hn::Mul(t, t), hn::Sub(hn::Set(d, 3.0f), hn::Mul(hn::Set(d, 2.0f), t)));
}

/// mix on lanes: a + (b - a) t.
inline VF mix_lanes(VF a, VF b, VF t) { return hn::Add(a, hn::Mul(hn::Sub(b, a), t)); }

/// lattice_hash's finaliser on lanes, from the hash's mix of the lattice indices `h`.
inline VU lattice_hash_of_mix(VU h, uint32_t salt) {
  const DU du;
  h = hn::Xor(h, hn::Set(du, salt * 0x9e3779b9u));
  h = hn::Xor(h, hn::ShiftRight<16>(h));
  h = hn::Mul(h, hn::Set(du, 0x85ebca6bu));
  h = hn::Xor(h, hn::ShiftRight<13>(h));
  h = hn::Mul(h, hn::Set(du, 0xc2b2ae35u));
  return hn::Xor(h, hn::ShiftRight<16>(h));
}

/// lattice_value(lattice_hash(...)) on lanes from the hash's mix of the lattice indices `h`.
inline VF lattice_value_of_mix(VU h, uint32_t salt) {
  const DF df;
  const auto top = hn::BitCast(DI(), hn::ShiftRight<8>(lattice_hash_of_mix(h, salt)));  // < 2^24: exact as float
  return hn::Mul(hn::ConvertTo(df, top), hn::Set(df, 1.0f / 16777216.0f));
}

/// lattice_value(lattice_hash(x, y, 0, salt)) on lanes (x, y are the lattice indices as u32).
inline VF lattice_value_lanes(VU x, VU y, uint32_t salt) {
  const DU du;
  return lattice_value_of_mix(hn::Xor(hn::Mul(x, hn::Set(du, 0x8da6b343u)), hn::Mul(y, hn::Set(du, 0xd8163841u))), salt);
}

/// lattice_value(lattice_hash(x, y, z, salt)) on lanes.
inline VF lattice_value_lanes(VU x, VU y, VU z, uint32_t salt) {
  const DU du;
  const VU xy = hn::Xor(hn::Mul(x, hn::Set(du, 0x8da6b343u)), hn::Mul(y, hn::Set(du, 0xd8163841u)));
  return lattice_value_of_mix(hn::Xor(xy, hn::Mul(z, hn::Set(du, 0xcb1ab31fu))), salt);
}

/// Derivative of smooth_weight on lanes: 6 t (1 - t).
inline VF smooth_slope_lanes(VF t) {
  const DF d;
  return hn::Mul(hn::Mul(hn::Set(d, 6.0f), t), hn::Sub(hn::Set(d, 1.0f), t));
}

/// value_noise2 on lanes; with `dx`, `dy` also its gradient (per unit of x and y).
inline VF value_noise2_lanes(VF x, VF y, uint32_t salt, VF* dx = nullptr, VF* dy = nullptr) {
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
inline VF value_noise3_lanes(VF x, VF y, VF z, uint32_t salt) {
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
inline VF fbm2_lanes(VF x, VF y, int octaves, uint32_t salt) {
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
inline VF smoothstep_lanes(float e0, float e1, VF x) {
  const DF d;
  const VF t = hn::Div(hn::Sub(x, hn::Set(d, e0)), hn::Set(d, e1 - e0));
  return smooth_weight_lanes(hn::Min(hn::Max(t, hn::Zero(d)), hn::Set(d, 1.0f)));
}

/// mix of a three-channel colour constant towards another, per channel k.
inline VF mix_channel(VF c, const float* to, int k, VF t) { return mix_lanes(c, hn::Set(DF(), to[k]), t); }

/// lattice_value(lattice_hash(x, y, z, salt)) on lanes of x with y and z the same on every lane.
inline VF lattice_value_lanes(VU x, uint32_t y, uint32_t z, uint32_t salt) {
  const DU du;
  return lattice_value_of_mix(hn::Xor(hn::Mul(x, hn::Set(du, 0x8da6b343u)), hn::Set(du, y * 0xd8163841u ^ z * 0xcb1ab31fu)),
                              salt);
}

}  // namespace silva::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // SILVA_RENDER_SHADING_NOISE_LANES_INL_HPP
