#pragma once
/// @file The specular part of the surface shading: a GGX (Trowbridge-Reitz) microfacet lobe with
/// Smith visibility and Schlick Fresnel for the sun, and a roughness-aware Fresnel weight for the
/// sky light mirrored by a surface. Pure arithmetic (no transcendental function), so every pixel is
/// the same bits on every machine.
#include "core/types.hpp"

namespace silva::render {

/// Smallest GGX alpha the sun is shaded with: the sun's disc is half a degree wide, so even a
/// water film shows a highlight of some size rather than a single sparkling pixel.
inline constexpr float kMinSunAlpha = 0.05f;

/// The GGX normal distribution D(h) = α² / (π ((n·h)² (α² - 1) + 1)²) for alpha = `alpha`.
float ggx_distribution(float n_dot_h, float alpha);

/// Smith height-correlated visibility V = G / (4 n·l n·v), in the approximation
/// 0.5 / (2 n·l n·v (1 - α) + (n·l + n·v) α) (exact at α = 0 and α = 1).
float smith_visibility(float n_dot_l, float n_dot_v, float alpha);

/// Schlick's Fresnel F0 + (1 - F0) (1 - cos)^5.
float schlick_fresnel(float f0, float cos_theta);

/// The GGX specular BRDF f = D V F for unit normal `n`, unit direction towards the viewer `to_eye`
/// and unit direction towards the light `to_light`, perceptual roughness `roughness` (α =
/// max(roughness², kMinSunAlpha)) and normal-incidence reflectance `f0`; 0 where either
/// direction is below the surface. Radiance = f · illuminance · n·l.
float ggx_specular(const Vec3f& n, const Vec3f& to_eye, const Vec3f& to_light, float roughness, float f0);

/// Fraction of the surrounding (sky) radiance a surface mirrors towards the viewer, integrated over
/// its GGX lobe: Karis's analytic fit of the split-sum environment BRDF (Unreal Engine 4 mobile),
/// with its exp2(-9.28 n·v) replaced by the polynomial (1 - n·v)^6 (within 0.03 of it), so
///   r = roughness (-1, -0.0275, -0.572, 0.022) + (1, 0.0425, 1.04, -0.04)
///   a = min(r0², (1 - n·v)^6) r0 + r1;  weight = F0 (-1.04 a + r2) + 1.04 a + r3, at least 0.
float ambient_specular_weight(float n_dot_v, float roughness, float f0);

/// Weight of the sun light a thin back-lit card lets through, from `card_dot_light` (its
/// camera-facing normal · the direction to the light) and `view_dot_light` (the viewing direction ·
/// the direction to the light): 0 unless the light is behind the card (card_dot_light < 0), then a
/// diffuse part -card_dot_light plus a forward-scattering lobe 1.5 max(view_dot_light, 0)^8
/// (looking towards the sun through the leaves makes them glow).
float back_light_transmission(float card_dot_light, float view_dot_light);

/// Fraction of the sky a mirrored ray of unit-direction z component `z` sees from inside a forest:
/// trunks and crowns hide the horizon, the sky overhead shows through the canopy gaps,
/// 0.3 + 0.7 smoothstep(0.05, 0.7, z) (0.3 below the horizon, where the fit's ground bounce is).
float forest_sky_view(float z);

/// The mirror direction of unit `to_eye` about unit `n`: 2 (n·e) n - e.
inline Vec3f reflect_to_eye(const Vec3f& n, const Vec3f& to_eye) { return n * (2.0f * n.dot(to_eye)) - to_eye; }

}  // namespace silva::render
