#include "render/sky.hpp"

#include <algorithm>
#include <cmath>

#include "render/shading_noise.hpp"

namespace silva::render {

namespace {
constexpr uint32_t kCloudSalt = 0xc10d;
constexpr uint32_t kStarSalt = 0x57a2;
constexpr float kCloudPlaneHeight = 1500.0f;  ///< Metres above the camera.
constexpr float kStarCellsPerRadian = 700.0f;

float smoothstep(float e0, float e1, float x) {
  const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return smooth_weight(t);
}

/// x^(2^k) by repeated squaring (exact sequence of multiplies, no pow).
float pow2k(float x, int k) {
  for (int i = 0; i < k; ++i) x *= x;
  return x;
}
}  // namespace

Sky::Sky(const LightingPreset& preset) : preset_(preset) {
  to_sun = sun_direction(preset);
  // The direct light fades out as it sets, so a preset with the sun just below the horizon has no sun light.
  sun_radiance = to_vec(preset.sun_color) * (preset.sun_intensity * smoothstep(-0.02f, 0.05f, to_sun.z()));
  zenith = to_vec(preset.sky_zenith) * preset.sky_intensity;
  horizon = to_vec(preset.sky_horizon) * preset.sky_intensity;
  sky_light = (zenith + horizon) * (0.5f * preset.ambient_intensity);
  ground_light = to_vec(preset.ground_color) * preset.ambient_intensity;
  const float sun_up = std::clamp(to_sun.z() * 4.0f, 0.0f, 1.0f);
  cloud_lit_ = to_vec(preset.cloud_color).cwiseProduct(sun_radiance * (0.25f * sun_up) + zenith * 1.2f);
  const double radius = double(preset.sun_disc_deg) * 0.5 * 3.14159265358979323846 / 180.0;
  disc_cos_ = float(std::cos(radius));
  disc_edge_cos_ = float(std::cos(radius * 1.25));
}

Vec3f Sky::gradient(const Vec3f& dir) const {
  const float up = std::max(dir.z(), 0.0f);
  const float h = 1.0f - up;
  const float to_horizon = h * h * h;
  Vec3f c = zenith + (horizon - zenith) * to_horizon;
  if (dir.z() < 0.0f) c *= 1.0f - 0.5f * std::min(-dir.z() * 4.0f, 1.0f);
  const float cs = std::max(dir.dot(to_sun), 0.0f);
  const float glow = preset_.sun_glow * (0.06f * pow2k(cs, 3) + 0.5f * pow2k(cs, 6)) * (1.0f - preset_.moon);
  const float horizon_glow = preset_.sun_glow * 0.25f * cs * cs * to_horizon * (1.0f - preset_.moon);
  return c + sun_radiance * (glow + horizon_glow);
}

float Sky::cloud_density(const Vec3f& dir) const {
  if (preset_.cloud_cover <= 0.0f || dir.z() <= 0.01f) return 0.0f;
  const float t = kCloudPlaneHeight / (dir.z() * preset_.cloud_scale);
  const float d = fbm2(dir.x() * t, dir.y() * t, 5, kCloudSalt);
  const float threshold = 0.5f + (0.5f - preset_.cloud_cover) * 0.5f;
  return smoothstep(threshold - 0.05f, threshold + 0.15f, d) * smoothstep(0.02f, 0.2f, dir.z());
}

float Sky::star(const Vec3f& dir) const {
  if (preset_.star_density <= 0.0f || dir.z() <= 0.0f) return 0.0f;
  const int32_t x = int32_t(std::floor(dir.x() * kStarCellsPerRadian));
  const int32_t y = int32_t(std::floor(dir.y() * kStarCellsPerRadian));
  const int32_t z = int32_t(std::floor(dir.z() * kStarCellsPerRadian));
  const float v = lattice_value(lattice_hash(x, y, z, kStarSalt));
  if (v >= preset_.star_density) return 0.0f;
  return (0.02f + 0.3f * pow2k(v / preset_.star_density, 2)) * smoothstep(0.0f, 0.15f, dir.z());
}

Vec3f Sky::radiance(const Vec3f& dir) const {
  Vec3f c = gradient(dir);
  const float cs = dir.dot(to_sun);
  if (cs > disc_edge_cos_) {
    const float disc = smoothstep(disc_edge_cos_, disc_cos_, cs);
    const Vec3f disc_col = to_vec(preset_.sun_color) * preset_.sun_disc_intensity;
    c += (disc_col - c) * disc;
  }
  c += Vec3f::Constant(star(dir));
  const float cloud = cloud_density(dir);
  if (cloud > 0.0f) {
    const float lit = 0.75f + 0.25f * std::max(cs, 0.0f);
    c += (cloud_lit_ * lit * (1.1f - 0.35f * cloud) - c) * (0.95f * cloud);
  }
  return c;
}

Vec3f Sky::ambient(const Vec3f& n) const {
  const float up = 0.5f + 0.5f * n.z();
  return ground_light + (sky_light - ground_light) * up;
}

}  // namespace silva::render
