// light_rough_surfaces: light_surface on SIMD lanes, compiled once per Highway target
// (foreach_target) and chosen at run time. Every operation is a correctly rounded add, multiply,
// divide or square root in light_surface's order (Eigen's 3-term float dot products sum
// a0 + (a1 + a2)); branches become selects, and min/max/clamp are compare-and-select with
// std::min/max/clamp's operand order, so every target returns light_surface's bits.
#include "render/surface_light.hpp"

#include "render/brdf.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/surface_light_lanes.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace silva::render::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using VF = hn::Vec<DF>;
static_assert(HWY_MAX_BYTES / sizeof(float) <= SurfaceBatch::kPadding, "a vector never reads past the batch's padding");

constexpr float kInvPiF = 0.318309886183790672f;

/// Three lanes vectors: x, y, z (or r, g, b).
struct V3 {
  VF x, y, z;
};

/// a.b as Eigen sums a 3-vector of floats: a0 b0 + (a1 b1 + a2 b2).
VF dot(const V3& a, const V3& b) {
  return hn::Add(hn::Mul(a.x, b.x), hn::Add(hn::Mul(a.y, b.y), hn::Mul(a.z, b.z)));
}

/// a.b with b the same on every lane.
VF dot(DF d, const V3& a, const Vec3f& b) { return dot(a, V3{hn::Set(d, b.x()), hn::Set(d, b.y()), hn::Set(d, b.z())}); }

/// std::max(a, b): b where a < b, else a.
VF max_of(VF a, VF b) { return hn::IfThenElse(hn::Lt(a, b), b, a); }

/// std::min(a, b): b where b < a, else a.
VF min_of(VF a, VF b) { return hn::IfThenElse(hn::Lt(b, a), b, a); }

/// std::clamp(v, lo, hi).
VF clamp_of(VF v, VF lo, VF hi) { return hn::IfThenElse(hn::Lt(v, lo), lo, hn::IfThenElse(hn::Lt(hi, v), hi, v)); }

/// forest_sky_view on lanes.
VF sky_view(DF d, VF z) {
  const VF t = clamp_of(hn::Mul(hn::Sub(z, hn::Set(d, 0.05f)), hn::Set(d, 1.0f / 0.65f)), hn::Zero(d), hn::Set(d, 1.0f));
  const VF smooth = hn::Mul(hn::Mul(hn::Mul(hn::Set(d, 0.7f), t), t), hn::Sub(hn::Set(d, 3.0f), hn::Mul(hn::Set(d, 2.0f), t)));
  return hn::Add(hn::Set(d, 0.3f), smooth);
}

/// ggx_specular on lanes, given n·l and n·v (0 where either is not positive).
VF ggx(DF d, VF n_dot_l, VF n_dot_v, VF v_dot_l, VF roughness, VF f0) {
  const VF one = hn::Set(d, 1.0f), two = hn::Set(d, 2.0f);
  const VF one_plus_vl = max_of(hn::Add(one, v_dot_l), hn::Set(d, 1e-6f));
  const VF sum = hn::Add(n_dot_v, n_dot_l);
  const VF alpha = max_of(hn::Mul(roughness, roughness), hn::Set(d, kMinSunAlpha)), a2 = hn::Mul(alpha, alpha);
  const VF dd = hn::Add(hn::Mul(hn::Mul(sum, sum), hn::Sub(a2, one)), hn::Mul(two, one_plus_vl));
  const VF smith = hn::Add(hn::Mul(hn::Mul(hn::Mul(two, n_dot_l), n_dot_v), hn::Sub(one, alpha)),
                           hn::Mul(hn::Add(n_dot_l, n_dot_v), alpha));
  const VF numerator = hn::Mul(hn::Mul(a2, hn::Set(d, 0.5f * kInvPiF)),
                               hn::Mul(hn::Mul(hn::Set(d, 4.0f), one_plus_vl), one_plus_vl));
  const VF dv = hn::Div(numerator, hn::Mul(hn::Mul(dd, dd), smith));
  const VF c = clamp_of(hn::Sqrt(hn::Mul(hn::Set(d, 0.5f), one_plus_vl)), hn::Zero(d), one);
  const VF m = hn::Sub(one, c), m2 = hn::Mul(m, m);
  const VF fresnel = hn::Add(f0, hn::Mul(hn::Sub(one, f0), hn::Mul(hn::Mul(m2, m2), m)));
  const auto lit = hn::And(hn::Gt(n_dot_l, hn::Zero(d)), hn::Gt(n_dot_v, hn::Zero(d)));
  return hn::IfThenElseZero(lit, hn::Mul(dv, fresnel));
}

/// ambient_specular_weight on lanes.
VF specular_weight(DF d, VF n_dot_v, VF roughness, VF f0) {
  const VF one = hn::Set(d, 1.0f);
  const VF r0 = hn::Sub(one, roughness), r1 = hn::Sub(hn::Set(d, 0.0425f), hn::Mul(hn::Set(d, 0.0275f), roughness));
  const VF r2 = hn::Sub(hn::Set(d, 1.04f), hn::Mul(hn::Set(d, 0.572f), roughness));
  const VF r3 = hn::Sub(hn::Mul(hn::Set(d, 0.022f), roughness), hn::Set(d, 0.04f));
  const VF m = hn::Sub(one, clamp_of(n_dot_v, hn::Zero(d), one)), m2 = hn::Mul(m, m);
  const VF m6 = hn::Mul(hn::Mul(m2, m2), m2);
  const VF a = hn::Add(hn::Mul(min_of(hn::Mul(r0, r0), m6), r0), r1);
  const VF a104 = hn::Mul(hn::Set(d, 1.04f), a);
  return max_of(hn::Add(hn::Add(hn::Mul(f0, hn::Sub(r2, a104)), a104), r3), hn::Zero(d));
}

/// The SH irradiance of channel c at normal n (IrradianceSH::irradiance, never negative).
VF ambient(DF d, const IrradianceSH& sh, int c, const V3& n) {
  const VF x = n.x, y = n.y, z = n.z;
  const VF terms[8] = {y,
                       z,
                       x,
                       hn::Mul(x, y),
                       hn::Mul(y, z),
                       hn::Sub(hn::Mul(hn::Mul(hn::Set(d, 3.0f), z), z), hn::Set(d, 1.0f)),
                       hn::Mul(x, z),
                       hn::Sub(hn::Mul(x, x), hn::Mul(y, y))};
  VF e = hn::Set(d, sh.coeffs[0][c]);
  for (int k = 0; k < 8; ++k) e = hn::Add(e, hn::Mul(hn::Set(d, sh.coeffs[size_t(k) + 1][c]), terms[k]));
  return max_of(e, hn::Zero(d));
}

/// light_rough_surfaces for one target.
void LightRoughSurfacesImpl(const SurfaceLighting& lighting, const SurfaceBatch& batch, Vec3f* out) {
  if (batch.padded_size() == 0) return;  // `out` may be an empty vector's null data()
  const DF d;
  const size_t N = hn::Lanes(d);
  const Sky& sky = lighting.sky;
  const MirroredSky& mirror = lighting.mirror;
  const bool sun_up = sky.sun_illuminance.maxCoeff() > 0.0f;
  const VF zero = hn::Zero(d), one = hn::Set(d, 1.0f), inv_pi = hn::Set(d, kInvPiF);
  float* rgb = out->data();  // Vec3f is three packed floats
  for (size_t i = 0; i < batch.padded_size(); i += N) {
    const auto load = [&](SurfaceBatch::Field f) { return hn::LoadU(d, batch.field(f) + i); };
    const V3 albedo{load(SurfaceBatch::kAlbedoR), load(SurfaceBatch::kAlbedoG), load(SurfaceBatch::kAlbedoB)};
    const V3 n{load(SurfaceBatch::kNormalX), load(SurfaceBatch::kNormalY), load(SurfaceBatch::kNormalZ)};
    const V3 card{load(SurfaceBatch::kCardX), load(SurfaceBatch::kCardY), load(SurfaceBatch::kCardZ)};
    const V3 view{load(SurfaceBatch::kViewX), load(SurfaceBatch::kViewY), load(SurfaceBatch::kViewZ)};
    const VF roughness = load(SurfaceBatch::kRoughness), f0 = load(SurfaceBatch::kF0);
    const VF translucency = load(SurfaceBatch::kTranslucency), sun_visible = load(SurfaceBatch::kSunVisible);
    const VF fog = load(SurfaceBatch::kFog), canopy = load(SurfaceBatch::kCanopy);
    const VF open = hn::Sub(one, canopy);
    const VF fog_light = hn::Sub(one, hn::Mul(hn::Set(d, kFogCanopyShade), canopy));
    const V3 to_eye{hn::Neg(view.x), hn::Neg(view.y), hn::Neg(view.z)};
    const VF ambient_visible =
        hn::Sub(one, hn::Mul(hn::Set(d, lighting.ao_strength), hn::Sub(one, load(SurfaceBatch::kAo))));
    const VF n_dot_l = dot(d, n, sky.to_sun), n_dot_v = dot(n, to_eye);
    const VF v_dot_l = dot(d, view, sky.to_sun);
    // Sun: lit front faces, or back light through translucent cards.
    const auto sun_on = sun_up ? hn::Gt(sun_visible, zero) : hn::Lt(one, zero);
    const auto front = hn::And(sun_on, hn::Gt(n_dot_l, zero));
    const auto back = hn::AndNot(front, hn::And(sun_on, hn::Gt(translucency, zero)));
    const VF spec = ggx(d, n_dot_l, n_dot_v, dot(d, to_eye, sky.to_sun), roughness, f0);
    const VF card_dot_l = dot(d, card, sky.to_sun);
    const VF c = max_of(v_dot_l, zero), c2 = hn::Mul(c, c), c4 = hn::Mul(c2, c2);
    const VF through = hn::IfThenZeroElse(hn::Ge(card_dot_l, zero),
                                          hn::Add(hn::Neg(card_dot_l), hn::Mul(hn::Mul(hn::Set(d, 1.5f), c4), c4)));
    const VF amount = hn::Mul(hn::Mul(hn::Mul(through, translucency), hn::Set(d, lighting.foliage_translucency)), inv_pi);
    // Mirrored sky along the reflection, by its z only.
    const VF k = hn::Mul(hn::Set(d, 2.0f), n_dot_v);
    const VF mz = hn::Sub(hn::Mul(n.z, k), to_eye.z);
    const auto up = hn::Gt(mz, zero);
    const VF abs_z = hn::Abs(mz), view_fraction = sky_view(d, mz);
    const VF mirror_weight = hn::Mul(hn::Mul(specular_weight(d, n_dot_v, roughness, f0), ambient_visible), open);
    // Fog towards the view direction.
    const VF cs = max_of(v_dot_l, zero);
    VF toward = hn::Mul(cs, cs);
    toward = hn::Mul(toward, toward);
    toward = hn::Mul(toward, toward);
    const auto fogged = hn::Not(hn::Le(fog, zero));
    VF channel[3];
    const VF albedo_c[3] = {albedo.x, albedo.y, albedo.z};
    for (int ch = 0; ch < 3; ++ch) {
      const VF sun = hn::Mul(hn::Set(d, sky.sun_illuminance[ch]), sun_visible);
      const VF sky_part = hn::Mul(ambient(d, sky.ambient_sh, ch, n), open);
      VF diffuse = hn::Mul(hn::Add(sky_part, hn::Mul(hn::Set(d, lighting.canopy_light[ch]), canopy)), ambient_visible);
      diffuse = hn::IfThenElse(front, hn::Add(diffuse, hn::Mul(sun, n_dot_l)), diffuse);
      const VF front_light = hn::Mul(sun, hn::Mul(spec, n_dot_l));
      const VF back_light = hn::Mul(hn::Mul(hn::Mul(albedo_c[ch], hn::Set(d, kTransmissionTint[ch])), sun), amount);
      VF o = hn::Add(zero, hn::IfThenElse(front, front_light, hn::IfThenElseZero(back, back_light)));
      o = hn::Add(o, hn::Mul(hn::Mul(albedo_c[ch], diffuse), inv_pi));
      const VF level = hn::Set(d, mirror.level[ch]);
      const VF toward_z = hn::IfThenElse(up, hn::Set(d, mirror.up[ch]), hn::Set(d, mirror.down[ch]));
      const VF mirrored = hn::Mul(hn::Add(level, hn::Mul(hn::Sub(toward_z, level), abs_z)), view_fraction);
      o = hn::Add(o, hn::Mul(mirrored, mirror_weight));
      const VF color = hn::Mul(hn::Add(hn::Set(d, lighting.fog.in_scatter()[ch]),
                                       hn::Mul(hn::Set(d, lighting.fog.sun_scatter()[ch]), toward)),
                               fog_light);  // the fog over a surface under trees is partly in their shade
      channel[ch] = hn::IfThenElse(fogged, hn::Add(o, hn::Mul(hn::Sub(color, o), fog)), o);
    }
    hn::StoreInterleaved3(channel[0], channel[1], channel[2], d, rgb + 3 * i);
  }
}

/// The target this copy of the kernel was compiled for.
int64_t SurfaceLightTargetImpl() { return HWY_TARGET; }

}  // namespace silva::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace silva::render {

HWY_EXPORT(LightRoughSurfacesImpl);
HWY_EXPORT(SurfaceLightTargetImpl);

void light_rough_surfaces(const SurfaceLighting& lighting, const SurfaceBatch& batch, Vec3f* out) {
  HWY_DYNAMIC_DISPATCH(LightRoughSurfacesImpl)(lighting, batch, out);
}

int64_t surface_light_simd_target() { return HWY_DYNAMIC_DISPATCH(SurfaceLightTargetImpl)(); }

}  // namespace silva::render
#endif  // HWY_ONCE
