#include "render/surface_light.hpp"

#include <algorithm>
#include <cmath>

#include "render/brdf.hpp"

namespace silva::render {

namespace {
constexpr float kInvPi = 0.318309886183790672f;
}  // namespace

MirroredSky::MirroredSky(const Sky& sky)
    : up(sky.ambient(Vec3f(0, 0, 1)) * kInvPi),
      level((sky.ambient(Vec3f(1, 0, 0)) + sky.ambient(Vec3f(-1, 0, 0)) + sky.ambient(Vec3f(0, 1, 0)) +
             sky.ambient(Vec3f(0, -1, 0))) * (0.25f * kInvPi)),
      down(sky.ambient(Vec3f(0, 0, -1)) * kInvPi) {}

Vec3f MirroredSky::along(const Vec3f& dir) const {
  const float z = dir.z();
  return (level + ((z > 0.0f ? up : down) - level) * std::abs(z)) * forest_sky_view(z);
}

SurfaceLighting::SurfaceLighting(const Sky& sky, const HeightFog& fog, const LightingPreset& preset)
    : sky(sky), fog(fog), mirror(sky), ao_strength(preset.ao_strength),
      foliage_translucency(preset.foliage_translucency),
      canopy_light((sky.ambient(Vec3f(0, 0, 1)) + sky.sun_illuminance * std::max(sky.to_sun.z(), 0.0f))
                       .cwiseProduct(kCanopyScatter)) {}

Vec3f light_surface(const SurfaceLighting& lighting, const SurfaceSample& s) {
  const Sky& sky = lighting.sky;
  const Vec3f& n = s.normal;
  const Vec3f to_eye = -s.view_dir;
  const float ambient_visible = 1.0f - lighting.ao_strength * (1.0f - s.ao);
  const float open = 1.0f - s.canopy;
  Vec3f diffuse = (sky.ambient(n) * open + lighting.canopy_light * s.canopy) * ambient_visible;
  Vec3f out = Vec3f::Zero();
  if (sky.sun_illuminance.maxCoeff() > 0.0f && s.sun_visible > 0.0f) {
    const Vec3f sun = sky.sun_illuminance * s.sun_visible;
    const float n_dot_l = n.dot(sky.to_sun);
    if (n_dot_l > 0.0f) {
      diffuse += sun * n_dot_l;
      out += sun * (ggx_specular(n, to_eye, sky.to_sun, s.roughness, s.f0) * n_dot_l);
    } else if (s.translucency > 0.0f) {  // the card's normal faces the camera: the sun is behind it
      const float through = back_light_transmission(s.card_normal.dot(sky.to_sun), s.view_dir.dot(sky.to_sun));
      const float amount = through * s.translucency * lighting.foliage_translucency * kInvPi;
      out += s.albedo.cwiseProduct(kTransmissionTint).cwiseProduct(sun) * amount;
    }
  }
  out += s.albedo.cwiseProduct(diffuse) * kInvPi;
  const Vec3f mirrored_dir = reflect_to_eye(n, to_eye);
  Vec3f mirrored = lighting.mirror.along(mirrored_dir);  // the sky seen through a rough lobe
  if (s.roughness < kSharpReflection && mirrored_dir.z() > 0.0f)
    mirrored += (sky.diffuse(mirrored_dir) * forest_sky_view(mirrored_dir.z()) - mirrored) *
                (1.0f - s.roughness / kSharpReflection);
  out += mirrored * (ambient_specular_weight(n.dot(to_eye), s.roughness, s.f0) * ambient_visible * open);
  return lighting.fog.apply(out, s.fog, s.view_dir, 1.0f - kFogCanopyShade * s.canopy);
}

void SurfaceBatch::start(size_t capacity) {
  const size_t padded = (capacity + kPadding - 1) / kPadding * kPadding;
  for (size_t f = 0; f < kFieldCount; ++f) {
    if (fields_[f].size() < padded) fields_[f].resize(padded);
    data_[f] = fields_[f].data();
  }
  size_ = 0;
}

size_t SurfaceBatch::padded_size() const { return (size_ + kPadding - 1) / kPadding * kPadding; }

void SurfaceBatch::pad() {
  for (std::vector<float>& f : fields_) std::fill(f.begin() + std::ptrdiff_t(size_), f.begin() + std::ptrdiff_t(padded_size()), 0.0f);
}

}  // namespace silva::render
