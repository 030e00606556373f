#include "core/surface_overlay.hpp"

#include <algorithm>

#include "core/value_noise.hpp"

namespace silva {

namespace {
/// Noise salt of the ragged edge (its slot in render/noise_salts.hpp's table, kept free there).
constexpr uint32_t kOverlayEdgeSalt = 0x4a0;
}  // namespace

float overlay_edge(float uv_x, const Vec3f& position) {
  const float n = fbm2(position.x() * 1.3f, position.y() * 1.3f, 3, kOverlayEdgeSalt);
  return uv_x + kOverlayRagged * (2.0f * n - 1.0f);
}

float overlay_weight(float edge) {
  // (edge + s) / (s + s) is exactly 0.5 at edge 0, and smooth_weight(0.5) is exactly 0.5.
  const float t = std::clamp((edge + kOverlaySoftness) / (kOverlaySoftness + kOverlaySoftness), 0.0f, 1.0f);
  return 1.0f - smooth_weight(t);
}

}  // namespace silva
