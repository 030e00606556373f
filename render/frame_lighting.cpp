#include "render/frame_lighting.hpp"

#include <algorithm>
#include <cmath>

#include "core/rng.hpp"
#include "render/post.hpp"

namespace silva::render {

namespace {

/// A uniform draw from a [min, max] range (min == max gives min).
float draw_range(Rng& rng, const std::vector<double>& range) {
  return float(range[0] + (range[1] - range[0]) * rng.uniform_double());
}

/// Index of the weight a uniform draw `u` in [0, 1) lands on (zero weights are never drawn).
size_t draw_weighted(const std::vector<double>& weights, double u) {
  double total = 0;
  for (const double w : weights) total += w;
  const double target = u * total;
  double sum = 0;
  size_t last = 0;
  for (size_t i = 0; i < weights.size(); ++i) {
    if (weights[i] <= 0) continue;
    sum += weights[i];
    last = i;
    if (target < sum) return i;
  }
  return last;
}

/// Linear sRGB of the black-body chromaticity at `kelvin` with Y = 1 (Kim et al. 2002 cubic fits).
Vec3d planckian_rgb(double kelvin) {
  const double t = std::clamp(kelvin, 1667.0, 25000.0);
  const double t1 = 1e3 / t, t2 = t1 * t1, t3 = t2 * t1;
  const double x = t <= 4000.0 ? -0.2661239 * t3 - 0.2343589 * t2 + 0.8776956 * t1 + 0.179910
                               : -3.0258469 * t3 + 2.1070379 * t2 + 0.2226347 * t1 + 0.240390;
  const double x2 = x * x, x3 = x2 * x;
  const double y = t <= 2222.0   ? -1.1063814 * x3 - 1.34811020 * x2 + 2.18555832 * x - 0.20219683
                   : t <= 4000.0 ? -0.9549476 * x3 - 1.37418593 * x2 + 2.09137015 * x - 0.16748867
                                 : 3.0817580 * x3 - 5.87338670 * x2 + 3.75112997 * x - 0.37001483;
  const double X = x / y, Y = 1.0, Z = (1.0 - x - y) / y;
  return Vec3d(3.2404542 * X - 1.5371385 * Y - 0.4985314 * Z, -0.9692660 * X + 1.8760108 * Y + 0.0415560 * Z,
               0.0556434 * X - 0.2040259 * Y + 1.0572252 * Z);
}

}  // namespace

Vec3f white_balance_gains(float kelvin) {
  const Vec3d gains = planckian_rgb(FrameLighting::kNeutralWhiteK).cwiseQuotient(planckian_rgb(kelvin));
  return (gains / (0.2126 * gains.x() + 0.7152 * gains.y() + 0.0722 * gains.z())).cast<float>();
}

FrameLighting frame_lighting(const RunLighting& run, uint64_t seed, std::string_view sequence, uint64_t frame) {
  FrameLighting f;
  f.preset = run.preset;
  f.time_of_day = run.time_of_day;
  f.weather = run.weather;
  f.auto_exposure = run.auto_exposure;
  f.exposure_compensation_ev = run.exposure_compensation_ev;
  const LightingRandomizeConfig& r = run.randomize;
  if (!r.enabled) return f;
  f.randomized = true;
  Rng rng(seed, noise_key(sequence, frame), Purpose::LightingRandomize);
  f.preset.sun_elevation_deg = draw_range(rng, r.sun_elevation_deg);
  f.preset.sun_azimuth_deg = draw_range(rng, r.sun_azimuth_deg);
  f.preset.cloud_cover = draw_range(rng, r.cloud_cover);
  f.fog_density_scale = draw_range(rng, r.fog_density_scale);
  f.preset.fog_density = std::min(f.preset.fog_density * f.fog_density_scale, 1.0f);
  f.exposure_compensation_ev += draw_range(rng, r.exposure_compensation_ev);
  f.white_balance_k = draw_range(rng, r.white_balance_k);
  f.white_balance = white_balance_gains(f.white_balance_k);
  const double u = rng.uniform_double();
  if (!run.weather_choices.empty()) {
    const size_t w = draw_weighted(r.weather_weights, u);
    f.weather = r.weathers[w];
    f.preset.weather = run.weather_choices[w];
  }
  return f;
}

}  // namespace silva::render
