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
  const Vec3f half = to_eye + to_light;
  const float len2 = half.dot(half);
  if (len2 <= 0.0f) return 0.0f;
  const float inv_len = 1.0f / std::sqrt(len2);
  const float n_dot_h = n.dot(half) * inv_len, v_dot_h = to_eye.dot(half) * inv_len;
  const float alpha = std::max(roughness * roughness, kMinSunAlpha);
  return ggx_distribution(n_dot_h, alpha) * smith_visibility(n_dot_l, n_dot_v, alpha) * schlick_fresnel(f0, v_dot_h);
}

float ambient_specular_weight(float n_dot_v, float roughness, float f0) {
  const float r0 = 1.0f - roughness, r1 = 0.0425f - 0.0275f * roughness;
  const float r2 = 1.04f - 0.572f * roughness, r3 = 0.022f * roughness - 0.04f;
  const float m = 1.0f - std::clamp(n_dot_v, 0.0f, 1.0f), m2 = m * m, m6 = m2 * m2 * m2;
  const float a = std::min(r0 * r0, m6) * r0 + r1;
  return std::max(f0 * (r2 - 1.04f * a) + 1.04f * a + r3, 0.0f);
}

float forest_sky_view(float z) {
  const float t = std::clamp((z - 0.05f) / 0.65f, 0.0f, 1.0f);
  return 0.3f + 0.7f * t * t * (3.0f - 2.0f * t);
}

float back_light_transmission(float card_dot_light, float view_dot_light) {
  if (card_dot_light >= 0.0f) return 0.0f;
  const float c = std::max(view_dot_light, 0.0f), c2 = c * c, c4 = c2 * c2;
  return -card_dot_light + 1.5f * c4 * c4;
}

}  // namespace silva::render
