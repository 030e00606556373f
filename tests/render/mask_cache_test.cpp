// The scene's cache of mask opacity bits and leaf mips (render/mask_cache.hpp) and the tile grid's division-free
// tile index (render/bin.hpp): known answers against the scene's masks and plain division.
#include <gtest/gtest.h>

#include <memory>

#include "render/mask_cache.hpp"
#include "render/bin.hpp"

namespace silva::render {
namespace {

/// A width x height mask whose texel i has alpha (i * 37 + salt) mod 256.
std::shared_ptr<AlphaMask> patterned_mask(int width, int height, unsigned salt) {
  auto m = std::make_shared<AlphaMask>();
  m->width = width;
  m->height = height;
  for (int i = 0; i < width * height; ++i) m->alpha.push_back(uint8_t((unsigned(i) * 37u + salt) % 256u));
  return m;
}

/// A one-part, one-triangle scene whose part uses `mask`.
Scene scene_with(const std::shared_ptr<const AlphaMask>& mask, Mesh& mesh) {
  mesh.positions = {Vec3f(0, 0, 1), Vec3f(1, 0, 1), Vec3f(0, 1, 1)};
  mesh.uvs = {Vec2f(0, 0), Vec2f(1, 0), Vec2f(0, 1)};
  mesh.indices = {0, 1, 2};
  MeshPart part;
  part.index_count = 3;
  part.mask = mask;
  mesh.parts = {part};
  Scene scene;
  scene.meshes.emplace_back().lods = {&mesh};
  return scene;
}

TEST(MaskCache, KeepsTheMasksOfTheCurrentSceneOnly) {
  std::shared_ptr<const AlphaMask> a = patterned_mask(8, 8, 1), b = patterned_mask(33, 2, 2);
  const std::weak_ptr<const AlphaMask> a_alive = a;
  const AlphaMask* a_address = a.get();
  Mesh mesh_a, mesh_b;
  Scene scene_a = scene_with(a, mesh_a);
  MaskCache cache;
  cache.update(scene_a);
  ASSERT_NE(cache.find(a_address), nullptr);
  EXPECT_EQ(cache.find(a_address)->words, AlphaBits::of(*a).words);
  ASSERT_NE(cache.leaf_mips(a_address), nullptr);
  EXPECT_EQ(cache.leaf_mips(a_address)->coarse_levels(), 3);  // 4x4, 2x2, 1x1
  EXPECT_EQ(cache.find(b.get()), nullptr);
  // The scene lets go of the mask: the cache still holds it, so its address cannot be reused.
  a.reset();
  mesh_a.parts.clear();
  EXPECT_FALSE(a_alive.expired());
  Scene scene_b = scene_with(b, mesh_b);
  cache.update(scene_b);
  EXPECT_EQ(cache.find(a_address), nullptr);
  EXPECT_EQ(cache.leaf_mips(a_address), nullptr);
  EXPECT_TRUE(a_alive.expired());
  ASSERT_NE(cache.find(b.get()), nullptr);
  EXPECT_EQ(cache.find(b.get())->width, 33);
}

TEST(TileGrid, TileOfEqualsDivisionForEveryTileSizeAndPixel) {
  for (int ts = 1; ts <= 256; ++ts) {
    const TileGrid g = TileGrid::make(100, 100, ts);
    for (int p = 0; p <= 65535; ++p)
      if (g.tile_of(p) != p / ts) FAIL() << "tile size " << ts << ", pixel " << p << ": " << g.tile_of(p);
  }
}

}  // namespace
}  // namespace silva::render
