#include "render/shade.hpp"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/error.hpp"
#include "render/materials.hpp"
#include "render/post.hpp"
#include "render/shade_ao.hpp"
#include "render/shadow_lookup.hpp"
#include "render/sky.hpp"
#include "render/sky_fog.hpp"

namespace silva::render {

namespace {

/// Linear radiance arriving at a visible surface pixel, fog included.
Vec3f surface_radiance(const ShadeInputs& in, const Sky& sky, const HeightFog& fog, int u, int v,
                       const Vec3f& view_dir) {
  const GBuffer& g = in.gbuffer;
  const size_t i = size_t(v) * size_t(g.width) + size_t(u);
  const SurfacePoint s{g.position[i], g.normal[i], g.uv[i], g.material[i], g.variation[i]};
  const Vec3f albedo = material_albedo(s);
  const float n_dot_l = s.normal.dot(sky.to_sun);
  const float translucency = material_translucency(s.material) * in.preset.foliage_translucency;
  const float sun_facing = n_dot_l > 0.0f ? n_dot_l : -n_dot_l * translucency;
  Vec3f light = Vec3f::Zero();
  if (sun_facing > 0.0f && sky.sun_radiance.maxCoeff() > 0.0f) {
    const float visible = in.shadow ? shadow_visibility(*in.shadow, s.position, s.normal, sky.to_sun) : 1.0f;
    light = sky.sun_radiance * (sun_facing * visible);
  }
  const float ao = screen_space_ao(g, in.camera, u, v);
  light += sky.ambient(s.normal) * (1.0f - in.preset.ao_strength * (1.0f - ao));
  return fog.apply(albedo.cwiseProduct(light), s.position, view_dir);
}

/// Exposed, tone-mapped, grained, sRGB-encoded bytes of one pixel's radiance.
void encode_pixel(const ShadeInputs& in, float exposure, uint64_t key, size_t pixel, const Vec3f& radiance,
                  uint8_t* out) {
  const Vec3f grain = in.film_grain > 0.0f ? film_grain(in.seed, key, pixel, in.film_grain) : Vec3f::Zero();
  for (int c = 0; c < 3; ++c) out[c] = linear_to_srgb8(tonemap_aces(radiance[c] * exposure) + grain[c]);
}

}  // namespace

void shade_rgb(const ShadeInputs& in, std::vector<uint8_t>& rgb_out) {
  const GBuffer& g = in.gbuffer;
  if (g.width != in.camera.width || g.height != in.camera.height)
    throw InputError("shade_rgb: G-buffer " + std::to_string(g.width) + "x" + std::to_string(g.height) +
                     " does not match the camera's " + std::to_string(in.camera.width) + "x" +
                     std::to_string(in.camera.height));
  rgb_out.resize(g.size() * 3);
  const Sky sky(in.preset);
  const HeightFog fog(in.preset, sky, in.camera.position().cast<float>());
  const float exposure = exposure_scale(in.preset.exposure_ev);
  const uint64_t key = grain_key(in.sequence, in.frame);
  tbb::parallel_for(tbb::blocked_range<int>(0, g.height), [&](const tbb::blocked_range<int>& rows) {
    for (int v = rows.begin(); v < rows.end(); ++v) {
      for (int u = 0; u < g.width; ++u) {
        const size_t i = size_t(v) * size_t(g.width) + size_t(u);
        const Vec3f dir = in.camera.ray_direction(u, v).normalized().cast<float>();
        const Vec3f radiance = g.depth[i] == 0.0f ? sky.radiance(dir) : surface_radiance(in, sky, fog, u, v, dir);
        encode_pixel(in, exposure, key, i, radiance, &rgb_out[i * 3]);
      }
    }
  });
}

}  // namespace silva::render
