#include "render/weather_look.hpp"

#include <algorithm>

#include "core/value_noise.hpp"
#include "render/trail_material.hpp"

namespace silva::render {

namespace {
constexpr uint32_t kSnowSalt = 0x5e0f;
const Vec3f kSnowAlbedo(0.80f, 0.83f, 0.88f);
constexpr float kSnowPatchesPerMetre = 0.9f;
constexpr float kSnowOnCards = 0.35f;  ///< Snow cover kept on thin foliage cards (they bend and shed it).
constexpr float kWetSmoothing = 0.55f;  ///< Fraction of the roughness a water film removes on any surface ...
constexpr float kWetPooling = 0.3f;     ///< ... and the further fraction where the surface faces straight up.
constexpr uint32_t kPuddleSalt = 0x9dd1;
constexpr float kPuddlesPerMetre = 0.6f;  ///< Frequency of the hollows that hold water.
constexpr float kPuddleShare = 0.42f;     ///< How far below 1 the water's noise threshold falls at wetness 1.
constexpr float kPuddleDarkening = 0.6f;  ///< Albedo a puddle's muddy water takes away.
constexpr float kPuddleRoughness = 0.03f; ///< GGX roughness of still water.

float smoothstep01(float x) { return smooth_weight(std::clamp(x, 0.0f, 1.0f)); }
}  // namespace

WeatherLook::WeatherLook(const WeatherPreset& weather, TrailSurface trail)
    : wetness_(weather.wetness), snow_(weather.snow_cover), muddy_(trail == TrailSurface::Muddy) {}

float WeatherLook::wetness(const SurfacePoint& s) const {
  return muddy_ && s.material == Material::Trail ? std::max(wetness_, kMudWetness) : wetness_;
}

float WeatherLook::puddle(const SurfacePoint& s) const {
  if (s.material != Material::Trail) return 0.0f;
  const float standing = muddy_ ? trail_standing_water(s) : 0.0f;
  if (wetness_ <= 0.0f) return standing;
  const float x = s.position.x() * kPuddlesPerMetre, y = s.position.y() * kPuddlesPerMetre;
  const float hollow = 0.75f * value_noise2(x, y, kPuddleSalt) + 0.25f * value_noise2(3.7f * x, 3.7f * y, kPuddleSalt + 1);
  return std::max(standing, smoothstep01((hollow - (1.0f - kPuddleShare * wetness_)) * 12.0f));
}

Vec3f WeatherLook::albedo(const Vec3f& albedo, const SurfacePoint& s, float puddle) const {
  Vec3f a = albedo;
  const float wet = wetness(s);
  if (wet > 0.0f) {
    // Water fills the surface's pores: less light scattered back, colours deeper.
    const float grey = 0.2126f * a.x() + 0.7152f * a.y() + 0.0722f * a.z();
    const Vec3f saturated = (Vec3f::Constant(grey) + (a - Vec3f::Constant(grey)) * 1.4f).cwiseMax(0.0f) * 0.55f;
    a += (saturated - a) * wet;
    a *= 1.0f - kPuddleDarkening * puddle;
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

float WeatherLook::roughness(float dry, const Vec3f& n, float puddle) const {
  return wet_roughness(dry, n, puddle, wetness_);
}

float WeatherLook::roughness(const SurfacePoint& s, float dry, const Vec3f& n, float puddle) const {
  return wet_roughness(dry, n, puddle, wetness(s));
}

float WeatherLook::wet_roughness(float dry, const Vec3f& n, float puddle, float wetness) {
  if (wetness <= 0.0f) return dry;
  const float up = std::max(n.z(), 0.0f);
  const float wet = dry * (1.0f - wetness * (kWetSmoothing + kWetPooling * up * up));
  return wet + (kPuddleRoughness - wet) * puddle;
}

}  // namespace silva::render
