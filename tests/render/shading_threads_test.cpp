#include <gtest/gtest.h>

#include <tbb/task_arena.h>

#include <algorithm>

#include "core/error.hpp"

#include "render/shade.hpp"
#include "shading_scene.hpp"

namespace silva::render {
namespace {

/// The default camera model, or every optic on too (motion: 0.3 m sideways and 2 degrees of yaw).
CameraModel model_with(bool optics, const Camera& cam) {
  CameraModel m = camera_model(CameraConfig{}, cam);
  if (!optics) return m;
  m.chromatic_aberration = 0.01;
  m.depth_of_field = DepthOfField{1.0, 4.0, 20.0};
  const Mat4d& pose = cam.camera_to_world;
  m.motion = ExposureMotion{0.01, pose_from_angles(cam.position() - Vec3d(0, 0.15, 0), -1, -8, 0),
                            pose_from_angles(cam.position() + Vec3d(0, 0.15, 0), 1, -8, 0)};
  EXPECT_NE(m.motion->open_to_world, pose);
  return m;
}

/// The test image, `rows` high, shaded on `threads` threads; every third pixel carries a mask with
/// `mask_texels` texels across it (above 1: minified, the coverage blend on).
std::vector<uint8_t> shade_with_threads(int threads, const LightingPreset& preset, bool optics, int rows = 96,
                                        float mask_texels = 0.0f) {
  const Camera cam = test::test_camera(160, rows, 8);
  GBuffer g = test::plane_gbuffer(cam, Material::Ground, 12.0);
  for (size_t i = 0; i < g.size(); ++i) {  // a mix of materials across the image
    if (g.depth[i] > 0 && g.material[i] == Material::Ground) g.material[i] = Material(i / 7 % 12);
    if (i % 3 == 0) g.mask_texels[i] = mask_texels;
  }
  const ShadowMap map = test::plane_shadow_map(sun_direction(preset).cast<double>(), 256, 0.2, 2.0, 3.0);
  std::vector<uint8_t> rgb;
  tbb::task_arena arena(threads);
  arena.execute([&] { shade_rgb({g, cam, preset, &map, 11, "random", 2, model_with(optics, cam)}, rgb); });
  return rgb;
}

TEST(ShadingThreads, OneAndTwoThreadsGiveIdenticalBytes) {
  for (const auto& [name, preset] : builtin_presets())
    for (bool optics : {false, true}) {
      const std::vector<uint8_t> one = shade_with_threads(1, preset, optics);
      const std::vector<uint8_t> two = shade_with_threads(2, preset, optics);
      ASSERT_EQ(one.size(), size_t(160 * 96 * 3));
      EXPECT_EQ(one, two) << name << (optics ? " with every optic" : "");
    }
}

TEST(ShadingThreads, TheCoverageBlendGivesIdenticalBytesOnAnyThreadCount) {
  // Rows are shaded in bands of 16 and blended as their neighbours are ready: the bytes must not depend
  // on which thread took which band, every row must be written (90 rows: the last band is short), and
  // the blend must act.
  for (bool optics : {false, true}) {
    const std::vector<uint8_t> one = shade_with_threads(1, preset_day(), optics, 90, 4.0f);
    EXPECT_EQ(shade_with_threads(2, preset_day(), optics, 90, 4.0f), one) << optics;
    EXPECT_EQ(shade_with_threads(3, preset_day(), optics, 90, 4.0f), one) << optics;
    EXPECT_NE(shade_with_threads(1, preset_day(), optics, 90), one) << optics;  // no masks: not blended
    for (size_t row = 0; row < 90; ++row) {
      const auto first = one.begin() + std::ptrdiff_t(row * 160 * 3);
      EXPECT_TRUE(std::any_of(first, first + 160 * 3, [](uint8_t b) { return b != 0; })) << "row " << row;
    }
  }
}

TEST(ShadingThreads, MismatchedCameraIsAnInputError) {
  const Camera cam = test::test_camera(16, 8, 0);
  const GBuffer g = test::plane_gbuffer(test::test_camera(8, 8, 0), Material::Ground);
  const LightingPreset day = preset_day();
  std::vector<uint8_t> rgb;
  EXPECT_THROW(shade_rgb({g, cam, day, nullptr, 0, "random", 0, {}}, rgb), InputError);
}

}  // namespace
}  // namespace silva::render
