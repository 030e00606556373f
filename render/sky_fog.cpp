#include "render/sky_fog.hpp"

#include <algorithm>
#include <cmath>

#include "core/det_math.hpp"

namespace silva::render {

namespace {
constexpr float kInvPi = 0.318309886183790672f;

/// Optical depth of the fog column above height z: the integral of density(z') for z' > z.
double fog_column_depth(const LightingPreset& preset, double z) {
  if (preset.fog_height_falloff <= 0.0f) return preset.fog_density > 0.0f ? 1e3 : 0.0;  // a fog without a top
  return double(preset.fog_density) * det_exp(-double(preset.fog_height_falloff) * (z - double(preset.fog_height))) /
         double(preset.fog_height_falloff);
}
}  // namespace

HeightFogLight fog_light_transmittance(const LightingPreset& preset, const Vec3f& to_sun, float camera_z) {
  const double depth = fog_column_depth(preset, double(camera_z));
  const double sun_path = depth / std::max(double(to_sun.z()), kMinFogSunSine);
  return {float(det_exp(-depth * kDiffuseFogPath)), float(det_exp(-sun_path))};
}

HeightFog::HeightFog(const LightingPreset& preset, const Sky& sky, const Vec3f& camera_position)
    : sky_(sky),
      params_{camera_position, std::max(preset.fog_height_falloff, 0.0f),
              float(double(preset.fog_density) *
                    det_exp(-double(preset.fog_height_falloff) * double(camera_position.z() - preset.fog_height)))},
      light_(fog_light_transmittance(preset, sky.to_sun, camera_position.z())),
      in_scatter_(to_vec(preset.fog_tint).cwiseProduct(sky.mean_radiance * light_.diffuse +
                                                       sky.sun_illuminance * (0.25f * kInvPi * light_.sun)) *
                  kFogCanopyOpenness),
      sun_scatter_(to_vec(preset.fog_tint).cwiseProduct(sky.sun_illuminance) *
                   (0.3f * kInvPi * preset.fog_sun_scatter * light_.sun)) {}

float HeightFog::amount(const Vec3f& point) const {
  float a = 0.0f;
  amounts(&point, 1, &a);
  return a;
}

Vec3f HeightFog::color(const Vec3f& dir) const {
  const float cs = std::max(dir.dot(sky_.to_sun), 0.0f);
  float toward = cs * cs;
  toward *= toward;
  toward *= toward;
  return in_scatter_ + sun_scatter_ * toward;
}

Vec3f HeightFog::apply(const Vec3f& surface, float f, const Vec3f& dir, float light) const {
  if (f <= 0.0f) return surface;
  return surface + (color(dir) * light - surface) * f;
}

}  // namespace silva::render
