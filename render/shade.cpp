#include "render/shade.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/base_color.hpp"
#include "core/error.hpp"
#include "render/materials.hpp"
#include "render/post.hpp"
#include "render/shade_ao.hpp"
#include "render/shadow_lookup.hpp"
#include "render/sky.hpp"
#include "render/sky_fog.hpp"

namespace silva::render {

namespace {

/// Relative depth difference above which a half-resolution AO sample is not reused for a pixel.
constexpr float kAoReuseDepth = 0.05f;

/// Screen-space AO evaluated at the even pixels (2x, 2y) only (-1 where that pixel saw the sky).
struct HalfResAo {
  int width = 0, height = 0;  ///< Half-resolution size (rounded up).
  std::vector<float> ao;      ///< Row-major, width * height.

  /// Evaluates the samples in parallel rows.
  HalfResAo(const GBuffer& g, const Camera& camera) : width((g.width + 1) / 2), height((g.height + 1) / 2) {
    ao.resize(size_t(width) * size_t(height));
    tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
      for (int y = rows.begin(); y < rows.end(); ++y) {
        float* row = &ao[size_t(y) * size_t(width)];
        screen_space_ao_row(g, camera, 2 * y, 0, 2, width, row);
        for (int x = 0; x < width; ++x)
          if (g.depth[size_t(2 * y) * size_t(g.width) + size_t(2 * x)] == 0.0f) row[x] = -1.0f;
      }
    });
  }

  /// AO of full-resolution pixel (u, v): the sample of the nearest of the (up to 4) surrounding even
  /// pixels whose depth is within kAoReuseDepth of the pixel's, else evaluated for the pixel itself.
  float at(const GBuffer& g, const Camera& camera, int u, int v) const {
    const float depth = g.depth[size_t(v) * size_t(g.width) + size_t(u)];
    const int hx = u / 2, hy = v / 2;
    const int nx = std::min(hx + (u & 1), width - 1), ny = std::min(hy + (v & 1), height - 1);
    const float limit = kAoReuseDepth * depth;
    float best = -1.0f, best_diff = 0.0f;
    for (const auto& [x, y] : {std::pair{hx, hy}, std::pair{nx, hy}, std::pair{hx, ny}, std::pair{nx, ny}}) {
      const float a = ao[size_t(y) * size_t(width) + size_t(x)];
      if (a < 0.0f) continue;
      const float diff = std::abs(g.depth[size_t(2 * y) * size_t(g.width) + size_t(2 * x)] - depth);
      if (diff <= limit && (best < 0.0f || diff < best_diff)) best = a, best_diff = diff;
    }
    return best >= 0.0f ? best : screen_space_ao(g, camera, u, v);
  }
};

/// Linear radiance arriving at a visible surface pixel, fog included.
Vec3f surface_radiance(const ShadeInputs& in, const Sky& sky, const HeightFog& fog, float fog_amount,
                       float sun_visible, const HalfResAo& half_ao, int u, int v, const Vec3f& view_dir) {
  const GBuffer& g = in.gbuffer;
  const size_t i = size_t(v) * size_t(g.width) + size_t(u);
  const SurfacePoint s{g.position[i], g.normal[i], g.uv[i], g.material[i], g.variation[i]};
  const Vec3f albedo = g.base_color[i] != 0 ? unpack_srgb8(g.base_color[i]) : material_albedo(s);
  const float n_dot_l = s.normal.dot(sky.to_sun);
  const float translucency = material_translucency(s.material) * in.preset.foliage_translucency;
  const float sun_facing = n_dot_l > 0.0f ? n_dot_l : -n_dot_l * translucency;
  Vec3f light = Vec3f::Zero();
  if (sun_facing > 0.0f && sky.sun_radiance.maxCoeff() > 0.0f) {
    light = sky.sun_radiance * (sun_facing * sun_visible);
  }
  const float ao = half_ao.at(g, in.camera, u, v);
  light += sky.ambient(s.normal) * (1.0f - in.preset.ao_strength * (1.0f - ao));
  return fog.apply(albedo.cwiseProduct(light), fog_amount, view_dir);
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
  const HalfResAo half_ao(g, in.camera);
  tbb::parallel_for(tbb::blocked_range<int>(0, g.height), [&](const tbb::blocked_range<int>& rows) {
    std::vector<float> fog_amount(size_t(g.width)), sun_visible(size_t(g.width), 1.0f);
    std::vector<Vec3f> radiance(size_t(g.width)), grain(in.film_grain > 0.0f ? size_t(g.width) : 0);
    for (int v = rows.begin(); v < rows.end(); ++v) {
      const size_t row = size_t(v) * size_t(g.width);
      fog.amounts(&g.position[row], size_t(g.width), fog_amount.data());
      if (in.shadow && sky.sun_radiance.maxCoeff() > 0.0f)
        shadow_visibility_row(*in.shadow, &g.position[row], &g.normal[row], size_t(g.width), sky.to_sun, sun_visible.data());
      for (int u = 0; u < g.width; ++u) {
        const size_t i = row + size_t(u);
        const Vec3f dir = in.camera.ray_direction(u, v).normalized().cast<float>();
        radiance[size_t(u)] = g.depth[i] == 0.0f ? sky.radiance(dir)
                                                 : surface_radiance(in, sky, fog, fog_amount[size_t(u)],
                                                                    sun_visible[size_t(u)], half_ao, u, v, dir);
        if (!grain.empty()) grain[size_t(u)] = film_grain(in.seed, key, i, in.film_grain);
      }
      encode_srgb8_row(radiance.data()->data(), grain.empty() ? nullptr : grain.data()->data(), size_t(g.width), exposure,
                       &rgb_out[row * 3]);
    }
  });
}

}  // namespace silva::render
