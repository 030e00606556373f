// The trail seen by the renderer: one surface with the terrain (no step where the label changes),
// and its label edge on the 50 % line of its look.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/camera.hpp"
#include "render/renderer.hpp"
#include "core/surface_overlay.hpp"
#include "systems/prepare_scene.hpp"
#include "tests/common/test_library.hpp"
#include "world/world_generator.hpp"

namespace silva {
namespace {

/// G-buffer of a camera `height` metres above the trail at arc length s, looking almost straight
/// down; the scene is the terrain of the 3x3 chunks around that point (no objects).
render::GBuffer trail_view(const world::WorldContext& ctx, double s, double height) {
  const Vec3d p = ctx.trail.nav.position(s);
  const double size = ctx.chunk_size();
  const ChunkCoord at{int32_t(std::floor(p.x() / size)), int32_t(std::floor(p.y() / size))};
  std::vector<std::shared_ptr<const ChunkContent>> chunks;
  for (int dj = -1; dj <= 1; ++dj)
    for (int di = -1; di <= 1; ++di) {
      auto c = std::make_shared<ChunkContent>();
      c->coord = ChunkCoord{at.i + di, at.j + dj};
      world::add_terrain(ctx, *c);
      chunks.push_back(std::move(c));
    }
  const systems::FrameScene frame =
      systems::SceneBuilder(test::small_library()).build(std::move(chunks), p + Vec3d(0, 0, height), 40.0);
  Camera cam = Camera::from_fov(320, 320, 60, 0.05, 100);
  const Vec3d t = ctx.trail.nav.tangent(s);
  const double yaw = std::atan2(t.y(), t.x()) * 180.0 / 3.14159265358979323846;
  cam.camera_to_world = pose_from_angles(p + Vec3d(0, 0, height), yaw, -89, 0);
  render::GBuffer g;
  render::Renderer().render_gbuffer(frame.scene, cam, render::RenderOptions{}, g);
  return g;
}

/// Calls f(a, b) for every pair of horizontally or vertically adjacent pixels.
template <class F>
void for_each_neighbour_pair(const render::GBuffer& g, F f) {
  for (int v = 0; v < g.height; ++v)
    for (int u = 0; u < g.width; ++u) {
      const size_t i = size_t(v) * size_t(g.width) + size_t(u);
      if (u + 1 < g.width) f(i, i + 1);
      if (v + 1 < g.height) f(i, i + size_t(g.width));
    }
}

TEST(TrailEdge, NoHeightStepWhereTheLabelChanges) {
  const world::WorldContext ctx = world::make_world_context(test::small_world_config(31), test::small_library());
  ASSERT_TRUE(ctx.trail.enabled);
  size_t edges = 0;
  double worst = 0;
  for (double s : {5.0, 23.0, 41.0, 67.0}) {
    const render::GBuffer g = trail_view(ctx, s, 2.5);
    for_each_neighbour_pair(g, [&](size_t a, size_t b) {
      if (g.depth[a] == 0.0f || g.depth[b] == 0.0f) return;
      if ((g.role[a] == Role::Trail) == (g.role[b] == Role::Trail)) return;
      ++edges;
      worst = std::max(worst, double(std::abs(g.position[a].z() - g.position[b].z())));
    });
  }
  EXPECT_GT(edges, 400u);   // the trail's edges cross every view
  EXPECT_LT(worst, 0.01);  // < 1 cm between the two sides of the label edge
}

TEST(TrailEdge, LabelEdgeIsTheHalfBlendLine) {
  const world::WorldContext ctx = world::make_world_context(test::small_world_config(8), test::small_library());
  size_t trail = 0, blended = 0;
  for (double s : {12.0, 50.0}) {
    const render::GBuffer g = trail_view(ctx, s, 2.5);
    for (size_t i = 0; i < g.size(); ++i) {
      ASSERT_NE(g.depth[i], 0.0f);
      const float w = overlay_weight(overlay_edge(g.uv[i].x(), g.position[i]));
      // The class is the trail exactly where the look is at least half trail ...
      EXPECT_EQ(g.role[i] == Role::Trail, w >= 0.5f) << i;
      // ... and the trail material shades every pixel the blend (or the worn margin) touches.
      if (w > 0.0f) {
        EXPECT_EQ(g.material[i], Material::Trail) << i;
      }
      trail += g.role[i] == Role::Trail;
      blended += w > 0.0f && w < 1.0f;
    }
  }
  EXPECT_GT(trail, 20000u);
  EXPECT_GT(blended, 200u);  // the blend is soft, not a hard cut
}

}  // namespace
}  // namespace silva
