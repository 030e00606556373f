// Labels: alpha-tested cards, roles and instance ids per part, LOD selection and instance culling.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "core/error.hpp"
#include "raster_test_scenes.hpp"
#include "render/instance_cull.hpp"
#include "render/raster_conventions.hpp"
#include "render/leaf_mips.hpp"
#include "render/lighting.hpp"
#include "render/materials.hpp"
#include "render/renderer.hpp"
#include "render/shade.hpp"

namespace silva::render {
namespace {

using test::OwnedScene;

/// A camera at the origin whose axes are the world's (x right, y down, z forward).
Camera screen_camera(int w, int h) {
  Camera c = Camera::from_fov(w, h, 90.0, 0.05, 150.0);
  c.camera_to_world = Mat4d::Identity();
  return c;
}

/// G-buffer of `card` (instance id 7) in front of a ground quad at z = 5 filling the view.
GBuffer render_card_over_ground(const Camera& cam, Mesh card) {
  OwnedScene s;
  s.add_instance(s.add_mesh(std::move(card)), Affine3f::Identity(), 7);
  s.add_instance(s.add_mesh(test::make_quad({-9, -9, 5}, {-9, 9, 5}, {9, 9, 5}, {9, -9, 5}, Role::Ground)));
  Renderer renderer;
  GBuffer g;
  renderer.render_gbuffer(s.scene, cam, RenderOptions{}, g);
  return g;
}

/// Renders a frontal card at z = 2 over x, y in [-1.5, 1.5] with uvs 0..2 (repeat wrap) masked by
/// `mask`, and checks every pixel away from texel borders against AlphaMask::opaque. Returns the
/// numbers of opaque and hole pixels seen.
std::pair<int, int> expect_card_follows_mask(const std::shared_ptr<const AlphaMask>& mask) {
  const Camera cam = screen_camera(128, 96);
  Mesh card = test::make_quad({-1.5f, -1.5f, 2}, {-1.5f, 1.5f, 2}, {1.5f, 1.5f, 2}, {1.5f, -1.5f, 2}, Role::TreeCanopy,
                              false, mask);
  card.uvs = {Vec2f(0, 0), Vec2f(0, 2), Vec2f(2, 2), Vec2f(2, 0)};
  const GBuffer g = render_card_over_ground(cam, std::move(card));
  int opaque = 0, holes = 0;
  for (int v = 0; v < cam.height; ++v)
    for (int u = 0; u < cam.width; ++u) {
      const Vec3d d = cam.ray_direction(u, v) * 2.0;  // hit on the card plane z = 2
      if (std::abs(d.x()) > 1.49 || std::abs(d.y()) > 1.49) continue;
      // uv: u runs with x (0 at x = -1.5 to 2 at x = 1.5), v with y.
      const double tu = (d.x() + 1.5) / 3.0 * 2.0, tv = (d.y() + 1.5) / 3.0 * 2.0;
      const double fu = tu * mask->width, fv = tv * mask->height;
      if (std::abs(fu - std::round(fu)) < 1e-3 || std::abs(fv - std::round(fv)) < 1e-3) continue;  // texel border
      const bool want = mask->opaque(float(tu), float(tv));
      const size_t i = size_t(v) * size_t(cam.width) + size_t(u);
      EXPECT_EQ(g.role[i], want ? Role::TreeCanopy : Role::Ground) << u << "," << v;
      EXPECT_EQ(g.instance_id[i], want ? 7u : 0u);
      EXPECT_FLOAT_EQ(g.depth[i], want ? 2.0f : 5.0f);
      if (::testing::Test::HasFailure()) return {opaque, holes};
      (want ? opaque : holes)++;
    }
  return {opaque, holes};
}

/// A width x height mask with the given alpha bytes and cutoff 0.5.
std::shared_ptr<const AlphaMask> make_mask(int width, int height, std::vector<uint8_t> alpha) {
  auto mask = std::make_shared<AlphaMask>();
  mask->width = width;
  mask->height = height;
  mask->alpha = std::move(alpha);
  mask->cutoff = 0.5f;
  return mask;
}

TEST(RasterLabels, AlphaMaskCutsTheCardInTheVisibilityPass) {
  std::mt19937 gen(5);
  std::vector<uint8_t> alpha;
  for (int i = 0; i < 64; ++i) alpha.push_back(uint8_t(gen() % 256));
  const auto [opaque, holes] = expect_card_follows_mask(make_mask(8, 8, alpha));
  EXPECT_GT(opaque, 500);
  EXPECT_GT(holes, 500);
}

TEST(RasterLabels, MasksWiderThanOneOpacityWordAreReadTexelByTexel) {
  // 37 x 5 texels: rows start inside 32-texel opacity words and texels cross word boundaries.
  std::mt19937 gen(9);
  std::vector<uint8_t> alpha;
  for (int i = 0; i < 37 * 5; ++i) alpha.push_back(uint8_t(gen() % 256));
  const auto [opaque, holes] = expect_card_follows_mask(make_mask(37, 5, alpha));
  EXPECT_GT(opaque, 500);
  EXPECT_GT(holes, 500);
}

TEST(RasterLabels, TinyMasksAreReadInsideTheirTexels) {
  // 1..5 texels across: every lane must read its own texel, the first and last included;
  // 127 and 128 sit on either side of the cutoff (127.5).
  for (const auto& alpha : std::vector<std::vector<uint8_t>>{
           {255}, {128, 127}, {127, 255, 0}, {255, 0, 0, 128}, {0, 255, 127, 0, 255}}) {
    SCOPED_TRACE(alpha.size());
    const auto [opaque, holes] = expect_card_follows_mask(make_mask(int(alpha.size()), 1, alpha));
    EXPECT_GT(opaque, 500);
    if (alpha.size() > 1) {
      EXPECT_GT(holes, 500);
    }
  }
}

TEST(RasterLabels, MaskTexelsMeasureHowMinifiedEachPixelsMaskIs) {
  // A 256 x 256 mask repeated twice over the 3 m card: 512 / 3 texels per metre; at z = 2 a pixel of the
  // 128-wide 90-degree camera (fx = 64) is 2 / 64 m wide, so 16/3 texels across. The ground has no mask.
  const Camera cam = screen_camera(128, 96);
  Mesh card = test::make_quad({-1.5f, -1.5f, 2}, {-1.5f, 1.5f, 2}, {1.5f, 1.5f, 2}, {1.5f, -1.5f, 2}, Role::TreeCanopy,
                              false, make_mask(256, 256, std::vector<uint8_t>(256 * 256, 255)));
  card.uvs = {Vec2f(0, 0), Vec2f(0, 2), Vec2f(2, 2), Vec2f(2, 0)};
  const GBuffer g = render_card_over_ground(cam, std::move(card));
  int card_pixels = 0;
  for (size_t i = 0; i < g.size(); ++i) {
    if (g.role[i] == Role::TreeCanopy) {
      EXPECT_NEAR(g.mask_texels[i], 16.0f / 3.0f, 1e-4f) << i;
      ++card_pixels;
    } else {
      EXPECT_EQ(g.mask_texels[i], 0.0f) << i;
    }
  }
  EXPECT_GT(card_pixels, 5000);
}

TEST(RasterLabels, LeafAlphaComesFromTheMipLevelOfThePixelsFootprint) {
  // Every texel its own leaf brightness; at 16/3 texels across a pixel (level 2) each pixel takes the mean
  // of a 4 x 4 block: the brightness varies about a quarter as much from pixel to pixel as between texels.
  std::mt19937 gen(3);
  std::vector<uint8_t> alpha(256 * 256);
  for (uint8_t& a : alpha) a = uint8_t(128 + gen() % 127);
  const auto mask = make_mask(256, 256, alpha);
  const Camera cam = screen_camera(128, 96);
  Mesh card = test::make_quad({-1.5f, -1.5f, 2}, {-1.5f, 1.5f, 2}, {1.5f, 1.5f, 2}, {1.5f, -1.5f, 2}, Role::TreeCanopy,
                              false, mask);
  card.uvs = {Vec2f(0, 0), Vec2f(0, 2), Vec2f(2, 2), Vec2f(2, 0)};
  const GBuffer g = render_card_over_ground(cam, std::move(card));
  const LeafMips mips = LeafMips::of(*mask);
  const auto spread = [](const std::vector<float>& x) {
    double mean = 0, sq = 0;
    for (const float v : x) mean += v / double(x.size());
    for (const float v : x) sq += (v - mean) * (v - mean) / double(x.size());
    return std::sqrt(sq);
  };
  std::vector<float> pixels, texels;
  for (size_t i = 0; i < g.size(); ++i) {
    if (g.role[i] != Role::TreeCanopy) continue;
    ASSERT_EQ(g.leaf[i], mips.alpha(*mask, g.uv[i].x(), g.uv[i].y(), g.mask_texels[i])) << i;
    pixels.push_back(leaf_brightness(g.leaf[i]));
  }
  for (const uint8_t a : alpha) texels.push_back(leaf_brightness(a));
  ASSERT_GT(pixels.size(), 5000u);
  EXPECT_LT(spread(pixels), 0.35 * spread(texels));
  EXPECT_GT(spread(pixels), 0.15 * spread(texels));
}

TEST(RasterLabels, OwnBaseColourFollowsUvIntoTheGBufferAndTheRgb) {
  const Camera cam = screen_camera(128, 96);
  auto colour = std::make_shared<BaseColor>();
  colour->width = 4;
  colour->height = 1;
  colour->srgb = {255, 0, 0, 255, 0, 0, 0, 0, 255, 0, 0, 255};  // red, red, blue, blue
  colour->factor = Vec3f(0.5f, 1.0f, 1.0f);
  // A frontal card at z = 2 over x, y in [-1.5, 1.5]; u runs with x from 0 to 1.
  Mesh card = test::make_quad({-1.5f, -1.5f, 2}, {-1.5f, 1.5f, 2}, {1.5f, 1.5f, 2}, {1.5f, -1.5f, 2}, Role::Obstacle);
  card.uvs = {Vec2f(0, 0), Vec2f(0, 1), Vec2f(1, 1), Vec2f(1, 0)};
  card.parts[0].base_color = colour;
  const GBuffer g = render_card_over_ground(cam, std::move(card));
  std::vector<uint8_t> rgb;
  shade_rgb({g, cam, preset_day(), nullptr, 1, "random", 0, {}}, rgb);
  int red = 0, blue = 0, procedural = 0;
  for (int v = 0; v < cam.height; ++v)
    for (int u = 0; u < cam.width; ++u) {
      const Vec3d d = cam.ray_direction(u, v) * 2.0;  // hit on the card plane z = 2
      const size_t i = size_t(v) * size_t(cam.width) + size_t(u);
      const uint8_t* px = &rgb[3 * i];
      if (std::abs(d.x()) > 1.5 || std::abs(d.y()) > 1.5) {
        ASSERT_EQ(g.base_color[i], 0u) << "the procedural ground keeps its material";
        ++procedural;
        continue;
      }
      const double tu = (d.x() + 1.5) / 3.0;
      if (tu > 0.14 && tu < 0.36) {  // between the two red texel centres: pure (0.5, 0, 0)
        const Vec3f a = unpack_srgb8(g.base_color[i]);
        ASSERT_NEAR(a.x(), 0.5f, 3e-3f);
        ASSERT_EQ(a.y(), 0.0f);
        ASSERT_EQ(a.z(), 0.0f);
        ASSERT_GT(px[0], 2 * std::max(px[1], px[2]) + 10) << u << "," << v;
        ++red;
      } else if (tu > 0.64 && tu < 0.86) {  // between the blue texel centres: pure (0, 0, 1)
        ASSERT_EQ(unpack_srgb8(g.base_color[i]), Vec3f(0, 0, 1));
        ASSERT_GT(px[2], 2 * std::max(px[0], px[1]) + 10) << u << "," << v;
        ++blue;
      }
    }
  EXPECT_GT(red, 500);
  EXPECT_GT(blue, 500);
  EXPECT_GT(procedural, 500);
}

TEST(RasterLabels, PartRolesInstanceIdsAndVariationsSurvive) {
  const Camera cam = screen_camera(96, 64);
  // One mesh, two parts: left quad "trunk", right quad "canopy".
  Mesh m = test::make_quad({-1, -1, 0}, {-1, 1, 0}, {0, 1, 0}, {0, -1, 0}, Role::TreeTrunk);
  m.append(test::make_quad({0, -1, 0}, {0, 1, 0}, {1, 1, 0}, {1, -1, 0}, Role::TreeCanopy));
  m.parts[1].material = Material::Leaves;
  OwnedScene s;
  const uint32_t mesh = s.add_mesh(std::move(m));
  s.add_instance(mesh, test::place(Vec3f(-1.2f, 0, 3)), 0x01020003u, 11);
  s.add_instance(mesh, test::place(Vec3f(1.2f, 0, 3)), 0xff000001u, 22);
  Renderer renderer;
  GBuffer g;
  renderer.render_gbuffer(s.scene, cam, RenderOptions{}, g);
  const auto at = [&](double x, double y, double z) {
    const int u = int(cam.fx * x / z + cam.cx), v = int(cam.fy * y / z + cam.cy);
    return size_t(v) * size_t(cam.width) + size_t(u);
  };
  const struct {
    double x;
    Role role;
    uint32_t id, variation;
    Material material;
  } expect[] = {{-1.7, Role::TreeTrunk, 0x01020003u, 11, Material::Ground},
                {-0.7, Role::TreeCanopy, 0x01020003u, 11, Material::Leaves},
                {0.7, Role::TreeTrunk, 0xff000001u, 22, Material::Ground},
                {1.7, Role::TreeCanopy, 0xff000001u, 22, Material::Leaves}};
  for (const auto& e : expect) {
    const size_t i = at(e.x, 0.3, 3.0);
    EXPECT_EQ(g.role[i], e.role);
    EXPECT_EQ(g.instance_id[i], e.id);
    EXPECT_EQ(g.variation[i], e.variation);
    EXPECT_EQ(g.material[i], e.material);
  }
  const size_t sky = at(0.0, 0.0, 3.0);  // between the two instances: nothing
  EXPECT_EQ(g.role[sky], Role::Background);
  EXPECT_EQ(g.depth[sky], 0.0f);
  EXPECT_EQ(g.instance_id[sky], 0u);
}

TEST(RasterLabels, LodFollowsProjectedSizeAndCanBeForcedOff) {
  const Camera cam = screen_camera(64, 64);
  Mesh full = test::make_quad({-0.5f, -0.5f, 0}, {-0.5f, 0.5f, 0}, {0.5f, 0.5f, 0}, {0.5f, -0.5f, 0}, Role::TreeTrunk);
  Mesh coarse = test::make_quad({-0.5f, -0.5f, 0}, {-0.5f, 0.5f, 0}, {0.5f, 0.5f, 0}, {0.5f, -0.5f, 0}, Role::Shrub);
  OwnedScene s;
  s.meshes.push_back(std::make_unique<Mesh>(std::move(full)));
  s.meshes.push_back(std::make_unique<Mesh>(std::move(coarse)));
  MeshLods& two = s.scene.meshes.emplace_back();
  two.lods = {s.meshes[0].get(), s.meshes[1].get()};
  two.lod_screen_sizes = {0.2f};
  s.add_instance(0, test::place(Vec3f(-1, 0, 2)), 1);    // diameter 1.41 m at 2 m: ~0.7 of the height
  s.add_instance(0, test::place(Vec3f(3, 0, 20), 0.0f, 4.0f), 2);  // ~0.14 of the height
  s.add_instance(0, test::place(Vec3f(0, 0, -5)), 3);    // behind the camera
  Renderer renderer;
  GBuffer g;
  RenderStats stats;
  renderer.render_gbuffer(s.scene, cam, RenderOptions{}, g, &stats);
  ASSERT_EQ(renderer.instance_lods().size(), 3u);
  EXPECT_EQ(renderer.instance_lods()[0], 0u);
  EXPECT_EQ(renderer.instance_lods()[1], 1u);
  EXPECT_EQ(renderer.instance_lods()[2], kCulled);
  EXPECT_EQ(stats.instances_submitted, 3u);
  EXPECT_EQ(stats.instances_culled, 1u);
  EXPECT_EQ(stats.triangles_submitted, 4u);
  std::set<Role> roles(g.role.begin(), g.role.end());
  EXPECT_TRUE(roles.count(Role::TreeTrunk) && roles.count(Role::Shrub));
  RenderOptions no_lod;
  no_lod.lod = false;
  renderer.render_gbuffer(s.scene, cam, no_lod, g);
  EXPECT_EQ(renderer.instance_lods()[1], 0u);
  roles = std::set<Role>(g.role.begin(), g.role.end());
  EXPECT_FALSE(roles.count(Role::Shrub));
}

TEST(RasterLabels, BadSceneInputIsAnInputError) {
  const Camera cam = screen_camera(16, 16);
  OwnedScene s;
  s.add_mesh(test::make_quad({-1, -1, 2}, {-1, 1, 2}, {1, 1, 2}, {1, -1, 2}, Role::Ground));
  s.add_instance(3);  // no such mesh
  Renderer renderer;
  GBuffer g;
  EXPECT_THROW(renderer.render_gbuffer(s.scene, cam, RenderOptions{}, g), InputError);
  s.scene.instances[0].mesh = 0;
  s.meshes[0]->indices[2] = 99;  // index past the vertices
  EXPECT_THROW(renderer.render_gbuffer(s.scene, cam, RenderOptions{}, g), InputError);
  s.meshes[0]->indices[2] = 2;
  RenderOptions bad_tile;
  bad_tile.tile_size = 12;
  EXPECT_THROW(renderer.render_gbuffer(s.scene, cam, bad_tile, g), InputError);
  EXPECT_NO_THROW(renderer.render_gbuffer(s.scene, cam, RenderOptions{}, g));
}

}  // namespace
}  // namespace silva::render
