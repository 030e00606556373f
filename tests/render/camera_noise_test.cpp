// Sensor noise of the camera model: the normal draws, and the bytes of flat grey cards against
// the shot + read noise model propagated through the tone curve and sRGB by this test's own formulas.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/camera_model.hpp"
#include "render/camera_encode.hpp"
#include "render/post.hpp"
#include "render/shade.hpp"
#include "shading_scene.hpp"

namespace silva::render {
namespace {

TEST(CameraNoise, QuantileTableIsStandardNormal) {
  double sum = 0, sum_sq = 0;
  for (int i = 0; i < 65536; ++i) {
    const double q = normal_quantile(uint16_t(i));
    sum += q;
    sum_sq += q * q;
  }
  EXPECT_NEAR(sum / 65536, 0.0, 1e-6);
  EXPECT_NEAR(sum_sq / 65536, 1.0, 1e-5);
  EXPECT_NEAR(normal_quantile(32768), 0.0, 1e-3);
  EXPECT_NEAR(normal_quantile(uint16_t(65536 * 0.8413)), 1.0, 2e-3);  // Phi(1) = 0.8413
  EXPECT_LT(normal_quantile(0), -4.0f);
}

TEST(CameraNoise, DrawsRepeatPerFrameAndDifferAcrossFrames) {
  const uint64_t k4 = noise_key("random", 4), k5 = noise_key("random", 5);
  EXPECT_EQ(k4, noise_key("random", 4));
  EXPECT_NE(k4, k5);
  EXPECT_NE(k4, noise_key("autopilot", 4));
  int differ = 0;
  for (uint64_t i = 0; i < 1000; ++i) {
    EXPECT_EQ(sensor_normals(9, k4, i), sensor_normals(9, k4, i));
    differ += sensor_normals(9, k4, i) != sensor_normals(9, k5, i) ? 1 : 0;
  }
  EXPECT_GT(differ, 990);
}

/// Narkowicz's ACES fit scaled to reach white at signal 1 (the camera's tone curve).
double aces(double x) {
  x = std::max(x, 0.0);
  return std::min(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14) * (3.16 / 2.54), 1.0);
}

/// The unrounded 8-bit sRGB code of exposed linear value x: 255 * sRGB(ACES(x)) (IEC 61966-2-1).
double exact_code(double x) {
  const double c = std::clamp(aces(x), 0.0, 1.0);
  return 255.0 * (c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055);
}

/// The exposed linear value whose noiseless code is `code` (bisection on the formulas).
double level_for_code(double code) {
  double lo = 0, hi = 20;
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    (exact_code(mid) < code ? lo : hi) = mid;
  }
  return lo;
}

/// The model's std-dev in codes at exposed value x: the linear std-dev sqrt(e + r^2) / (full_well / gain)
/// with e = clamp(x, 0, 1) * full_well / gain, carried through ACES, sRGB and rounding by integrating
/// over the normal distribution.
double model_sigma(double x, const SensorNoise& s) {
  const double electrons = s.full_well_e / s.gain;
  const double sigma = std::sqrt(std::clamp(x, 0.0, 1.0) * electrons + s.read_noise_e * s.read_noise_e) / electrons;
  double w_sum = 0, m1 = 0, m2 = 0;
  for (int k = -4000; k <= 4000; ++k) {
    const double z = k * 0.0015, w = std::exp(-0.5 * z * z);
    const double code = std::round(exact_code(x + sigma * z));
    w_sum += w;
    m1 += w * code;
    m2 += w * code * code;
  }
  m1 /= w_sum;
  return std::sqrt(m2 / w_sum - m1 * m1);
}

/// Mean and std-dev of the codes of a 256 x 256 flat card of exposed value x (every channel).
std::pair<double, double> card_codes(const CameraModel& model, float x) {
  const Camera cam = Camera::from_fov(256, 256, 90, 0.05, 150);
  RowEncoder encoder(cam, model, 1.0f, 42, noise_key("random", 7));
  const std::vector<float> row(256 * 3, x);
  std::vector<uint8_t> out(256 * 3);
  double n = 0, m1 = 0, m2 = 0;
  for (int v = 0; v < 256; ++v) {
    encoder.encode(v, row.data(), out.data());
    for (uint8_t c : out) {
      n += 1;
      m1 += c;
      m2 += double(c) * c;
    }
  }
  m1 /= n;
  return {m1, std::sqrt(m2 / n - m1 * m1)};
}

TEST(CameraNoise, GreyCardsFollowTheShotAndReadNoiseModel) {
  for (const SensorNoise& sensor : {SensorNoise{}, SensorNoise{10000, 3, 8}, SensorNoise{20000, 10, 16}}) {
    CameraModel model;
    model.noise = sensor;
    for (double code : {20.0, 45.0, 180.0}) {
      const double x = level_for_code(code);
      const auto [mean, sigma] = card_codes(model, float(x));
      const double expected = model_sigma(x, sensor);
      SCOPED_TRACE("gain " + std::to_string(sensor.gain) + ", code " + std::to_string(code));
      EXPECT_NEAR(mean, code, 1.0 + 0.1 * expected);
      EXPECT_GT(expected, 0.9);  // above the 8-bit rounding, so the test can tell a wrong model
      EXPECT_NEAR(sigma, expected, 0.1 * expected);
    }
  }
}

TEST(CameraNoise, HighGainKeepsTheNoiseLevelButMovesItsColourToLuma) {
  CameraModel model;
  model.noise = SensorNoise{10000, 3, 8};
  const double x = level_for_code(45.0);
  for (double chroma : {0.5, 0.0}) {
    model.chroma = chroma;
    const auto [mean, sigma] = card_codes(model, float(x));
    EXPECT_NEAR(sigma, model_sigma(x, *model.noise), 0.1 * model_sigma(x, *model.noise)) << chroma;
  }
  // Without colour the three channels share one draw: every pixel of a grey card is grey.
  const Camera cam = Camera::from_fov(64, 8, 90, 0.05, 150);
  RowEncoder encoder(cam, model, 1.0f, 42, noise_key("random", 7));
  const std::vector<float> grey(64 * 3, float(x));
  std::vector<uint8_t> out(64 * 3);
  int noisy = 0;
  for (int v = 0; v < 8; ++v) {
    encoder.encode(v, grey.data(), out.data());
    for (size_t u = 0; u < 64; ++u) {
      EXPECT_EQ(out[3 * u], out[3 * u + 1]);
      EXPECT_EQ(out[3 * u + 1], out[3 * u + 2]);
      noisy += out[3 * u] != out[0] ? 1 : 0;
    }
  }
  EXPECT_GT(noisy, 100);  // and still noisy
  // A coloured card loses its colour: chroma 0 leaves its Rec.709 luminance in every channel.
  model.noise.reset();
  RowEncoder plain(cam, model, 1.0f, 42, 0);
  std::vector<float> red(64 * 3, 0.0f);
  for (size_t u = 0; u < 64; ++u) red[3 * u] = 0.5f;
  plain.encode(0, red.data(), out.data());
  EXPECT_EQ(out[0], out[1]);
  EXPECT_EQ(out[1], out[2]);
  EXPECT_EQ(out[0], linear_to_srgb8(tonemap_aces(0.2126f * 0.5f)));
}

TEST(CameraNoise, ReadNoiseRulesTheDarkAndShotNoiseTheBright) {
  const auto sigma = [](const SensorNoise& sensor, float x) {
    CameraModel model;
    model.noise = sensor;
    return card_codes(model, x).second;
  };
  // Read noise matters where there are few electrons, hardly at all where there are many.
  // 20 e- of read noise against 100 e- of signal (variance 5x) and against 5 000 e- (1.08x).
  EXPECT_GT(sigma({10000, 20, 1}, 0.01f), 1.5 * sigma({10000, 0, 1}, 0.01f));
  EXPECT_LT(sigma({10000, 20, 1}, 0.5f), 1.2 * sigma({10000, 0, 1}, 0.5f));
  // A deeper well (or lower gain) is quieter: shot noise relative to the signal falls as 1 / sqrt(e).
  EXPECT_NEAR(sigma({1000, 0, 1}, 0.5f) / sigma({4000, 0, 1}, 0.5f), 2.0, 0.2);
  EXPECT_NEAR(sigma({4000, 0, 4}, 0.5f), sigma({1000, 0, 1}, 0.5f), 1e-9);
}

TEST(CameraNoise, DarkAreasStayWithinFiveCodesAtTheDefaults) {
  const Camera cam = Camera::from_fov(256, 256, 90, 0.05, 150);
  CameraModel model = camera_model(CameraConfig{}, cam);
  ASSERT_TRUE(model.noise);
  model.vignetting = 0;  // a flat card: only the noise spreads the codes
  for (double code : {4.0, 8.0, 15.0, 25.0, 40.0, 60.0}) {
    const auto [mean, sigma] = card_codes(model, float(level_for_code(code)));
    EXPECT_LE(sigma, 5.0) << "code " << code;
    EXPECT_GT(sigma, 0.5) << "code " << code;  // the defaults do have visible noise
  }
}

TEST(CameraNoise, ImagesRepeatPerFrameAndDifferAcrossFrames) {
  const Camera cam = test::test_camera(48, 32, 5);
  const GBuffer g = test::plane_gbuffer(cam, Material::Ground);
  const LightingPreset day = preset_day();
  CameraModel noisy;
  noisy.noise = SensorNoise{};
  std::vector<uint8_t> a, b, c, clean;
  shade_rgb({g, cam, day, nullptr, 5, "autopilot", 3, noisy}, a);
  shade_rgb({g, cam, day, nullptr, 5, "autopilot", 3, noisy}, b);
  shade_rgb({g, cam, day, nullptr, 5, "autopilot", 4, noisy}, c);
  shade_rgb({g, cam, day, nullptr, 5, "autopilot", 3, {}}, clean);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  EXPECT_NE(a, clean);
  // Noise is small and nearly unbiased: the mean byte stays within half a code of the clean image.
  double diff = 0;
  for (size_t i = 0; i < a.size(); ++i) diff += double(a[i]) - double(clean[i]);
  EXPECT_LT(std::abs(diff / double(a.size())), 0.5);
}

}  // namespace
}  // namespace silva::render
