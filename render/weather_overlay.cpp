#include "render/weather_overlay.hpp"

#include <algorithm>
#include <cmath>

#include "core/rng.hpp"
#include "core/value_noise.hpp"

namespace silva::render {

namespace {
constexpr float kInvPi = 0.318309886183790672f;
constexpr float kStreakSlant = 0.12f;      ///< Horizontal pixels per pixel of fall (wind).
constexpr float kStreakCell = 9.0f;        ///< Sheared columns of one streak, pixels.
constexpr float kStreakOpacity = 0.22f;
constexpr float kFlakeOpacity = 0.85f;
constexpr int kLayers = 2;                 ///< Near and far drops; the far layer is half size.

/// Hashed value in [0, 1) of cell (x, y) of layer `layer`.
float cell_value(int32_t x, int32_t y, int32_t layer, uint32_t salt) { return lattice_value(lattice_hash(x, y, layer, salt)); }
}  // namespace

WeatherOverlay::WeatherOverlay(const WeatherPreset& weather, const Sky& sky, uint64_t seed, uint64_t frame_key,
                               int height, float canopy)
    : rain_(weather.rain_streaks * (1.0f - (1.0f - kUnderCanopyFall) * canopy)),
      snow_(weather.snowfall * (1.0f - (1.0f - kUnderCanopyFall) * canopy)),
      salt_(uint32_t(rng_bits(seed, frame_key, uint64_t(Purpose::WeatherOverlay), 0))),
      streak_length_(std::max(float(height) / 10.0f, 4.0f)),
      flake_cell_(std::max(float(height) / 45.0f, 4.0f)),
      streak_radiance_(sky.horizon_radiance * (1.3f * (1.0f - 0.7f * canopy))),
      flake_radiance_((sky.ambient(Vec3f::UnitZ()) + sky.sun_illuminance * std::max(sky.to_sun.z(), 0.0f)) *
                      (0.85f * kInvPi)) {}

float WeatherOverlay::streak(int u, int v) const {
  float coverage = 0.0f;
  for (int layer = 0; layer < kLayers; ++layer) {
    const float scale = layer == 0 ? 1.0f : 0.5f;
    const float cell_w = kStreakCell * scale, length = streak_length_ * scale, cell_h = length * 2.0f;
    const float x = float(u) - kStreakSlant * float(v);
    const int32_t column = int32_t(std::floor(x / cell_w));
    const float y = float(v) + cell_h * cell_value(column, 0, layer + 8, salt_);  // columns fall out of step
    const int32_t row = int32_t(std::floor(y / cell_h));
    if (cell_value(column, row, layer, salt_) >= rain_) continue;
    const float centre = (float(column) + 0.15f + 0.7f * cell_value(column, row, layer + 2, salt_)) * cell_w;
    const float top = float(row) * cell_h + (cell_h - length) * cell_value(column, row, layer + 4, salt_);
    const float along = (y - top) / length;
    if (along < 0.0f || along >= 1.0f) continue;
    const float across = std::abs(x - centre);
    if (across >= 1.0f) continue;
    coverage = std::max(coverage, (1.0f - across) * (1.0f - along) * (layer == 0 ? 1.0f : 0.6f));
  }
  return coverage;
}

float WeatherOverlay::flake(int u, int v) const {
  float coverage = 0.0f;
  for (int layer = 0; layer < kLayers; ++layer) {
    const float cell = flake_cell_ * (layer == 0 ? 1.6f : 0.8f);
    const float radius = std::max(cell * 0.12f, 0.7f);
    const int32_t cx = int32_t(std::floor(float(u) / cell)), cy = int32_t(std::floor(float(v) / cell));
    if (cell_value(cx, cy, layer + 16, salt_) >= snow_) continue;
    const float fx = (float(cx) + 0.2f + 0.6f * cell_value(cx, cy, layer + 18, salt_)) * cell;
    const float fy = (float(cy) + 0.2f + 0.6f * cell_value(cx, cy, layer + 20, salt_)) * cell;
    const float dx = float(u) + 0.5f - fx, dy = float(v) + 0.5f - fy;
    const float d2 = (dx * dx + dy * dy) / (radius * radius);
    if (d2 < 1.0f) coverage = std::max(coverage, 1.0f - d2);
  }
  return coverage;
}

void WeatherOverlay::apply_row(int v, Vec3f* radiance, int count) const {
  for (int u = 0; u < count; ++u) {
    Vec3f& c = radiance[u];
    if (rain_ > 0.0f) {
      const float s = streak(u, v);
      if (s > 0.0f) c += (streak_radiance_ - c) * (kStreakOpacity * s);
    }
    if (snow_ > 0.0f) {
      const float f = flake(u, v);
      if (f > 0.0f) c += (flake_radiance_ - c) * (kFlakeOpacity * f);
    }
  }
}

}  // namespace silva::render
