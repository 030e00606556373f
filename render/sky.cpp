#include "render/sky.hpp"

#include <algorithm>
#include <cmath>

#include "core/value_noise.hpp"
#include "render/sky_model.hpp"

namespace silva::render {

namespace {
constexpr uint32_t kCloudSalt = 0xc10d;
constexpr uint32_t kStarSalt = 0x57a2;
constexpr float kCloudPlaneHeight = 1500.0f;  ///< Metres above the camera.
constexpr float kStarCellsPerRadian = 700.0f;
constexpr float kStarLuminance = 1e-3f;       ///< kcd/m² of the brightest stars (1 cd/m²).
constexpr int kSkyRows = 33, kSkyCols = 65;   ///< Clear-sky table size.
constexpr double kPi = 3.14159265358979323846;

float smoothstep(float e0, float e1, float x) {
  const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return smooth_weight(t);
}

/// Below the horizon the sky darkens towards half its horizon value (haze over unseen ground).
float below_horizon(float z) { return z < 0.0f ? 1.0f - 0.5f * std::min(-z * 4.0f, 1.0f) : 1.0f; }

/// Luminance of a linear sRGB colour.
double luminance(const Vec3d& c) { return 0.2126 * c.x() + 0.7152 * c.y() + 0.0722 * c.z(); }
}  // namespace

Sky::Sky(const LightingPreset& preset) : preset_(preset) {
  to_sun = sun_direction(preset);
  const double elevation = double(preset.sun_elevation_deg) * kPi / 180.0;
  const double turbidity = double(preset.turbidity);
  const PreethamSky model(turbidity, elevation);
  const Vec3d sky_scale = to_vec(preset.sky_tint).cast<double>() * (double(preset.sky_intensity) * kPreethamSkyCalibration);
  const Vec3d sun_dir = to_sun.cast<double>();

  // Tabulate the clear sky over (s = sqrt(cos θ), t = sin(γ/2)); γ from t, θ from s.
  table_.resize(size_t(kSkyRows) * size_t(kSkyCols));
  for (int r = 0; r < kSkyRows; ++r) {
    const double s = double(r) / (kSkyRows - 1);
    for (int c = 0; c < kSkyCols; ++c) {
      const double t = double(c) / (kSkyCols - 1);
      table_[size_t(r) * kSkyCols + size_t(c)] = model.rgb(s * s, 2.0 * std::asin(t)).cwiseProduct(sky_scale).cast<float>();
    }
  }

  // The sun through the atmosphere, then through the clouds; faded out as it sets.
  const float cover = std::clamp(preset.cloud_cover, 0.0f, 1.0f);
  const float set_fade = smoothstep(-0.02f, 0.05f, to_sun.z());
  const Vec3d clear_sun = sun_transmittance(turbidity, elevation) * kSolarIlluminance *
                          double(preset.sun_intensity * set_fade);
  sun_illuminance = clear_sun.cwiseProduct(to_vec(preset.sun_tint).cast<double>()).cast<float>() * (1.0f - cover * cover);

  // The overcast that replaces the clear sky: CIE overcast, whose horizontal illuminance is
  // 7π/9 Lz, lets cloud_transmittance of the clear sky's daylight through.
  const auto clear_d = [&](const Vec3d& d) -> Vec3d { return clear(d.cast<float>()).cast<double>(); };
  const Vec3d clear_sky_h = horizontal_irradiance(clear_d);
  const double clear_day_h = luminance(clear_sun) * std::max(sun_dir.z(), 0.0) + luminance(clear_sky_h);
  const double overcast_lz = 9.0 / (7.0 * kPi) * double(preset.cloud_transmittance) * clear_day_h;
  overcast_zenith_ = (to_vec(preset.sky_tint).cast<double>() * overcast_lz).cast<float>();

  Vec3f horizon = Vec3f::Zero();
  for (int k = 0; k < 16; ++k) {
    const double phi = 2.0 * kPi * (k + 0.5) / 16.0;
    horizon += diffuse(Vec3f(float(std::cos(phi)), float(std::sin(phi)), 0.05f).normalized()) * (1.0f / 16.0f);
  }
  horizon_radiance = horizon;

  // Ambient: the diffuse sky above, the ground's bounce of everything arriving on it below.
  const auto diffuse_d = [&](const Vec3d& d) -> Vec3d { return diffuse(d.cast<float>()).cast<double>(); };
  const Vec3d ground_in = horizontal_irradiance(diffuse_d) + sun_illuminance.cast<double>() * std::max(sun_dir.z(), 0.0);
  const Vec3d bounce = ground_in.cwiseProduct(to_vec(preset.ground_albedo).cast<double>()) / kPi;
  ambient_sh = fit_irradiance_sh([&](const Vec3d& d) -> Vec3d { return d.z() > 0.0 ? diffuse_d(d) : bounce; });
  mean_radiance = ambient_sh.coeffs[0] * float(1.0 / kPi);  // the constant term of the irradiance is π x the mean
  for (Vec3f& c : ambient_sh.coeffs) c *= preset.ambient_intensity;

  // The disc carries the direct light spread over its solid angle (it clips, as a real sun does).
  const double radius = double(preset.sun_disc_deg) * 0.5 * kPi / 180.0;
  disc_radiance_ = Vec3f::Zero();
  if (radius > 0.0)
    disc_radiance_ = (clear_sun.cwiseProduct(to_vec(preset.sun_tint).cast<double>()) / (kPi * radius * radius)).cast<float>();
  disc_cos_ = float(std::cos(radius));
  disc_edge_cos_ = float(std::cos(radius * 1.25));
}

Vec3f Sky::clear(const Vec3f& dir) const {
  const float s = std::sqrt(std::clamp(dir.z(), 0.0f, 1.0f)) * float(kSkyRows - 1);
  const float t = std::sqrt(std::clamp(0.5f - 0.5f * dir.dot(to_sun), 0.0f, 1.0f)) * float(kSkyCols - 1);
  const int r0 = std::min(int(s), kSkyRows - 2), c0 = std::min(int(t), kSkyCols - 2);
  const float fr = s - float(r0), fc = t - float(c0);
  const Vec3f* row0 = &table_[size_t(r0) * kSkyCols + size_t(c0)];
  const Vec3f* row1 = row0 + kSkyCols;
  const Vec3f a = row0[0] + (row0[1] - row0[0]) * fc;
  const Vec3f b = row1[0] + (row1[1] - row1[0]) * fc;
  return (a + (b - a) * fr) * below_horizon(dir.z());
}

Vec3f Sky::overcast(const Vec3f& dir) const {
  const float z = std::max(dir.z(), 0.0f);
  return overcast_zenith_ * ((1.0f + 2.0f * z) * (1.0f / 3.0f) * below_horizon(dir.z()));
}

Vec3f Sky::diffuse(const Vec3f& dir) const {
  const Vec3f c = clear(dir);
  return c + (overcast(dir) - c) * std::clamp(preset_.cloud_cover, 0.0f, 1.0f);
}

float Sky::cloud_density(const Vec3f& dir) const {
  if (preset_.cloud_cover <= 0.0f || dir.z() <= 0.01f) return 0.0f;
  const float t = kCloudPlaneHeight / (dir.z() * preset_.cloud_scale);
  const float d = fbm2(dir.x() * t, dir.y() * t, 5, kCloudSalt);
  const float threshold = 0.5f + (0.5f - preset_.cloud_cover) * 0.5f;
  return smoothstep(threshold - 0.05f, threshold + 0.15f, d) * smoothstep(0.02f, 0.2f, dir.z());
}

float Sky::star(const Vec3f& dir) const {
  if (preset_.star_density <= 0.0f || dir.z() <= 0.0f) return 0.0f;
  const int32_t x = int32_t(std::floor(dir.x() * kStarCellsPerRadian));
  const int32_t y = int32_t(std::floor(dir.y() * kStarCellsPerRadian));
  const int32_t z = int32_t(std::floor(dir.z() * kStarCellsPerRadian));
  const float v = lattice_value(lattice_hash(x, y, z, kStarSalt));
  if (v >= preset_.star_density) return 0.0f;
  const float relative = v / preset_.star_density;
  return kStarLuminance * (0.06f + 0.94f * relative * relative) * smoothstep(0.0f, 0.15f, dir.z());
}

Vec3f Sky::radiance(const Vec3f& dir) const {
  Vec3f c = diffuse(dir) + Vec3f::Constant(star(dir));
  const float cs = dir.dot(to_sun);
  const float cover = std::clamp(preset_.cloud_cover, 0.0f, 1.0f);
  const float cloud = cloud_density(dir);
  if (cloud > 0.0f) {
    // Cloud bases are the overcast's light; broken clouds are brighter, with a sunlit rim towards the sun.
    const float open = 1.0f - cover;
    const float towards = std::max(cs, 0.0f);
    const Vec3f lit = overcast(dir) * (1.0f + 1.5f * open * (0.6f + 0.4f * towards)) +
                      sun_illuminance * (0.02f * open * towards * towards);
    c += (to_vec(preset_.cloud_color).cwiseProduct(lit) * (1.1f - 0.35f * cloud) - c) * (0.95f * cloud);
  }
  // The disc shows where no cloud hides it, dimmed as the cover thickens (none under an overcast).
  if (cs > disc_edge_cos_ && to_sun.z() > -0.02f) {
    const float visible = (1.0f - cover * cover) * (1.0f - cloud);
    c += (disc_radiance_ * visible - c) * (smoothstep(disc_edge_cos_, disc_cos_, cs) * visible);
  }
  return c;
}

}  // namespace silva::render
