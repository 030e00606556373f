#include "render/brdf.hpp"

#include <algorithm>
#include <cmath>

namespace silva::render {

namespace {
constexpr float kInvPi = 0.318309886183790672f;

/// (1 - c)^5 for c in [0, 1].
float pow5_complement(float c) {
  const float m = 1.0f - c, m2 = m * m;
  return m2 * m2 * m;
}
}  // namespace

float ggx_distribution(float n_dot_h, float alpha) {
  const float a2 = alpha * alpha;
  const float d = n_dot_h * n_dot_h * (a2 - 1.0f) + 1.0f;
  return a2 * kInvPi / (d * d);
}

float smith_visibility(float n_dot_l, float n_dot_v, float alpha) {
  return 0.5f / (2.0f * n_dot_l * n_dot_v * (1.0f - alpha) + (n_dot_l + n_dot_v) * alpha);
}

float schlick_fresnel(float f0, float cos_theta) {
  return f0 + (1.0f - f0) * pow5_complement(std::clamp(cos_theta, 0.0f, 1.0f));
}

float ggx_specular(const Vec3f& n, const Vec3f& to_eye, const Vec3f& to_light, float roughness, float f0) {
  const float n_dot_l = n.dot(to_light), n_dot_v = n.dot(to_eye);
  if (n_dot_l <= 0.0f || n_dot_v <= 0.0f) return 0.0f;
  // With the half vector h = (v + l) / |v + l|: |v + l|² = 2 + 2 v·l, v·h = sqrt((1 + v·l) / 2) and
  // (n·h)² = (n·v + n·l)² / (2 + 2 v·l); D and V share one division.
  const float one_plus_vl = std::max(1.0f + to_eye.dot(to_light), 1e-6f);
  const float n_dot_h_sum = n_dot_v + n_dot_l;
  const float alpha = std::max(roughness * roughness, kMinSunAlpha), a2 = alpha * alpha;
  const float d = n_dot_h_sum * n_dot_h_sum * (a2 - 1.0f) + 2.0f * one_plus_vl;  // (n·h)² (α² - 1) + 1, times |v + l|²
  const float smith = 2.0f * n_dot_l * n_dot_v * (1.0f - alpha) + (n_dot_l + n_dot_v) * alpha;
  // D V = α² / (π ((n·h)² (α² - 1) + 1)²) · 0.5 / smith, with the |v + l|² factors of d restored.
  const float dv = a2 * (0.5f * kInvPi) * (4.0f * one_plus_vl * one_plus_vl) / (d * d * smith);
  return dv * schlick_fresnel(f0, std::sqrt(0.5f * one_plus_vl));
}

float ambient_specular_weight(float n_dot_v, float roughness, float f0) {
  const float r0 = 1.0f - roughness, r1 = 0.0425f - 0.0275f * roughness;
  const float r2 = 1.04f - 0.572f * roughness, r3 = 0.022f * roughness - 0.04f;
  const float m = 1.0f - std::clamp(n_dot_v, 0.0f, 1.0f), m2 = m * m, m6 = m2 * m2 * m2;
  const float a = std::min(r0 * r0, m6) * r0 + r1;
  return std::max(f0 * (r2 - 1.04f * a) + 1.04f * a + r3, 0.0f);
}

float forest_sky_view(float z) {
  const float t = std::clamp((z - 0.05f) * (1.0f / 0.65f), 0.0f, 1.0f);
  return 0.3f + 0.7f * t * t * (3.0f - 2.0f * t);
}

float back_light_transmission(float card_dot_light, float view_dot_light) {
  if (card_dot_light >= 0.0f) return 0.0f;
  const float c = std::max(view_dot_light, 0.0f), c2 = c * c, c4 = c2 * c2;
  return -card_dot_light + 1.5f * c4 * c4;
}

}  // namespace silva::render
