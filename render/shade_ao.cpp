#include "render/shade_ao.hpp"

#include <algorithm>

namespace silva::render {

namespace {
/// Sample offsets on the unit disc: 8 directions, alternating full and half radius.
constexpr float kPattern[8][2] = {{1.0f, 0.0f},       {0.354f, 0.354f},  {0.0f, 1.0f},   {-0.354f, 0.354f},
                                  {-1.0f, 0.0f},      {-0.354f, -0.354f}, {0.0f, -1.0f}, {0.354f, -0.354f}};
}  // namespace

float screen_space_ao(const GBuffer& g, const Camera& camera, int u, int v) {
  const size_t i = size_t(v) * size_t(g.width) + size_t(u);
  const Vec3f& p = g.position[i];
  const Vec3f& n = g.normal[i];
  // Screen offsets reach 0.6 kAoRadius at the pixel's depth, so most samples land within the radius.
  const float radius_px = std::clamp(float(camera.fx) * (0.6f * kAoRadius) / g.depth[i], 1.5f, 48.0f);
  const float inv_r2 = 1.0f / (kAoRadius * kAoRadius);
  float occlusion = 0.0f;
  for (const auto& o : kPattern) {
    const int su = std::clamp(u + int(o[0] * radius_px), 0, g.width - 1);
    const int sv = std::clamp(v + int(o[1] * radius_px), 0, g.height - 1);
    const size_t s = size_t(sv) * size_t(g.width) + size_t(su);
    if (s == i || g.depth[s] == 0.0f) continue;
    const Vec3f d = g.position[s] - p;
    const float d2 = d.squaredNorm();
    if (d2 <= 1e-8f || d2 >= kAoRadius * kAoRadius) continue;
    const float elevation = n.dot(d) / std::sqrt(d2);
    occlusion += std::max(elevation - 0.1f, 0.0f) * (1.0f - d2 * inv_r2);
  }
  return std::max(0.0f, 1.0f - occlusion * (1.5f / 8.0f));
}

}  // namespace silva::render
