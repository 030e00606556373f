#include "render/weather_look.hpp"

#include <algorithm>

#include "core/value_noise.hpp"

namespace silva::render {

namespace {
constexpr uint32_t kSnowSalt = 0x5e0f;
const Vec3f kSnowAlbedo(0.80f, 0.83f, 0.88f);
constexpr float kSnowPatchesPerMetre = 0.9f;
constexpr float kSnowOnCards = 0.35f;  ///< Snow cover kept on thin foliage cards (they bend and shed it).
constexpr float kWetSmoothing = 0.55f;  ///< Fraction of the roughness a water film removes on any surface ...
constexpr float kWetPooling = 0.3f;     ///< ... and the further fraction where the surface faces straight up.

float smoothstep01(float x) { return smooth_weight(std::clamp(x, 0.0f, 1.0f)); }
}  // namespace

WeatherLook::WeatherLook(const WeatherPreset& weather) : wetness_(weather.wetness), snow_(weather.snow_cover) {}

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
    if (material_response(s.material).translucency > 0.0f) w *= kSnowOnCards;
    a += (kSnowAlbedo - a) * w;
  }
  return a;
}

float WeatherLook::roughness(float dry, const Vec3f& n) const {
  if (wetness_ <= 0.0f) return dry;
  const float up = std::max(n.z(), 0.0f);
  return dry * (1.0f - wetness_ * (kWetSmoothing + kWetPooling * up * up));
}

}  // namespace silva::render
