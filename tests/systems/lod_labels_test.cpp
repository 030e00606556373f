// LOD changes triangles, never labels: a fixed capture view of the demo world rendered with
// render.lod = true and false agrees on the class of almost every pixel and loses no visible thing.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "render/renderer.hpp"
#include "systems/prepare_scene.hpp"
#include "tests/common/default_world.hpp"
#include "world/chunk_cache.hpp"
#include "world/chunk_regions.hpp"

namespace silva {
namespace {

/// Pixels per instance id (0 excluded).
std::map<uint32_t, size_t> instance_pixels(const render::GBuffer& g) {
  std::map<uint32_t, size_t> n;
  for (uint32_t id : g.instance_id)
    if (id != 0) ++n[id];
  return n;
}

TEST(LodLabels, FixedViewAgreesWithFullDetail) {
  const test::DefaultWorld w;  // the middle trail point looking along the trail, 1920x1080
  const Camera& camera = w.camera;
  world::ChunkCache cache(256);
  const systems::FrameScene frame =
      systems::SceneBuilder(*w.library)
          .build(cache.require(w.ctx, world::chunks_in_view(camera, w.ctx.chunk_size())), camera.position(),
                 w.cfg.render.ground_cover_distance);
  render::Renderer renderer;
  render::GBuffer full, lod;
  render::RenderOptions options;
  options.lod = false;
  renderer.render_gbuffer(frame.scene, camera, options, full);
  options.lod = true;
  renderer.render_gbuffer(frame.scene, camera, options, lod);

  size_t same = 0;
  for (size_t i = 0; i < full.size(); ++i) same += full.role[i] == lod.role[i] ? 1 : 0;
  const double agreement = double(same) / double(full.size());
  const auto full_pixels = instance_pixels(full), lod_pixels = instance_pixels(lod);
  size_t visible = 0, lost = 0;
  for (const auto& [id, n] : full_pixels) {
    if (n < 20) continue;
    ++visible;
    if (!lod_pixels.contains(id)) ++lost;
  }
  std::printf("class agreement %.3f %%; %zu instances of >= 20 px at lod = false, %zu of them gone at lod = true\n",
              100.0 * agreement, visible, lost);
  EXPECT_GE(agreement, 0.995);
  EXPECT_GT(visible, 100u);
  EXPECT_EQ(lost, 0u);
}

TEST(LodLabels, GroundCoverCutoffLiesBetweenThreeQuartersAndAllOfTheDistance) {
  EXPECT_DOUBLE_EQ(systems::ground_cover_cutoff(0, 40.0), 30.0);
  EXPECT_LT(systems::ground_cover_cutoff(0xffffffffu, 40.0), 40.0);
  EXPECT_GT(systems::ground_cover_cutoff(0xffffffffu, 40.0), 39.99);
}

}  // namespace
}  // namespace silva
