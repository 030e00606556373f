#include "render/weather_look.hpp"

#include <algorithm>

#include "render/shading_noise.hpp"

namespace silva::render {

namespace {
constexpr uint32_t kSnowSalt = 0x5e0f;
const Vec3f kSnowAlbedo(0.80f, 0.83f, 0.88f);
constexpr float kSnowPatchesPerMetre = 0.9f;
constexpr float kSheen = 0.35f;  ///< How mirror-like a wet surface is at grazing view (rough, not a puddle).

float smoothstep01(float x) { return smooth_weight(std::clamp(x, 0.0f, 1.0f)); }
}  // namespace

WeatherLook::WeatherLook(const WeatherPreset& weather, const Sky& sky)
    : wetness_(weather.wetness), snow_(weather.snow_cover), horizon_(sky.horizon_radiance) {}

Vec3f WeatherLook::albedo(const Vec3f& albedo, const SurfacePoint& s) const {
  Vec3f a = albedo;
  if (wetness_ > 0.0f) {
    // Water fills the surface's pores: less light scattered back, colours deeper.
    const float grey = 0.2126f * a.x() + 0.7152f * a.y() + 0.0722f * a.z();
    const Vec3f saturated = (Vec3f::Constant(grey) + (a - Vec3f::Constant(grey)) * 1.4f).cwiseMax(0.0f) * 0.55f;
    a += (saturated - a) * wetness_;
  }
  if (snow_ > 0.0f) {
    const float noise = value_noise2(s.position.x() * kSnowPatchesPerMetre, s.position.y() * kSnowPatchesPerMetre, kSnowSalt);
    const float lying = s.normal.z() - 0.45f + 0.6f * noise;  // where snow settles and stays
    float w = smoothstep01((lying - (1.0f - snow_)) * 4.0f) * snow_;
    if (s.material == Material::Trail) w *= 0.45f;  // trodden
    a += (kSnowAlbedo - a) * w;
  }
  return a;
}

Vec3f WeatherLook::sheen(const Vec3f& n, const Vec3f& view_dir, float ambient_visible) const {
  if (wetness_ <= 0.0f || n.z() <= 0.0f) return Vec3f::Zero();
  const float c = std::clamp(-n.dot(view_dir), 0.0f, 1.0f);
  const float m = 1.0f - c, m2 = m * m;
  const float fresnel = 0.02f + 0.98f * m2 * m2 * m;
  const float up = n.z() * n.z();
  return horizon_ * (kSheen * wetness_ * fresnel * up * up * ambient_visible);
}

}  // namespace silva::render
