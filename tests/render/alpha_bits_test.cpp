// Opacity bit tables of alpha masks (render/alpha_bits.hpp) and the tile grid's division-free
// tile index (render/bin.hpp): known answers against the byte masks and plain division.
#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "core/error.hpp"
#include "render/alpha_bits.hpp"
#include "render/bin.hpp"

namespace silva::render {
namespace {

/// A width x height mask of random alpha bytes.
std::shared_ptr<AlphaMask> random_mask(int width, int height, float cutoff, unsigned seed) {
  std::mt19937 gen(seed);
  auto m = std::make_shared<AlphaMask>();
  m->width = width;
  m->height = height;
  m->cutoff = cutoff;
  for (int i = 0; i < width * height; ++i) m->alpha.push_back(uint8_t(gen() % 256));
  return m;
}

TEST(AlphaBits, EveryTexelMatchesTheByteMask) {
  // Sizes below, at and across the 32-texel word boundary, and cutoffs on both sides of 0.5.
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{1, 1}, {5, 1}, {31, 1}, {32, 2}, {33, 3}, {64, 64}, {37, 5}})
    for (const float cutoff : {0.1f, 0.5f, 0.9f}) {
      const auto mask = random_mask(w, h, cutoff, unsigned(w * 100 + h));
      const AlphaBits bits = AlphaBits::of(*mask);
      ASSERT_EQ(bits.words.size(), size_t((w * h + 31) / 32));
      int opaque = 0;
      for (int i = 0; i < w * h; ++i) {
        ASSERT_EQ(bits.opaque_texel(i), mask->opaque_texel(i)) << w << "x" << h << " texel " << i;
        opaque += mask->opaque_texel(i) ? 1 : 0;
      }
      if (w * h >= 64) {
        EXPECT_GT(opaque, 0);
        EXPECT_LT(opaque, w * h);
      }
    }
}

TEST(AlphaBits, LookupsWrapLikeTheByteMask) {
  const auto mask = random_mask(37, 5, 0.5f, 11);
  const AlphaBits bits = AlphaBits::of(*mask);
  std::mt19937 gen(3);
  std::uniform_real_distribution<float> coord(-3.0f, 3.0f);
  for (int k = 0; k < 20000; ++k) {
    const float u = coord(gen), v = coord(gen);
    ASSERT_EQ(bits.opaque(u, v), mask->opaque(u, v)) << u << ", " << v;
  }
  // Texel 36 of row 0 is the last of the first row: u just below 1 reads it, u = 1 wraps to texel 0.
  EXPECT_EQ(bits.opaque(0.9999f, 0.1f), mask->opaque_texel(36));
  EXPECT_EQ(bits.opaque(1.0f, 0.1f), mask->opaque_texel(0));
}

TEST(AlphaBits, AMaskWhoseSizeDisagreesWithItsBytesIsAnInputError) {
  auto mask = random_mask(4, 4, 0.5f, 1);
  mask->alpha.pop_back();
  try {
    (void)AlphaBits::of(*mask);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("4x4"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("15 alpha values"), std::string::npos) << e.what();
  }
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

TEST(AlphaBitsCache, KeepsTheMasksOfTheCurrentSceneOnly) {
  std::shared_ptr<const AlphaMask> a = random_mask(8, 8, 0.5f, 1), b = random_mask(33, 2, 0.5f, 2);
  const std::weak_ptr<const AlphaMask> a_alive = a;
  const AlphaMask* a_address = a.get();
  Mesh mesh_a, mesh_b;
  Scene scene_a = scene_with(a, mesh_a);
  AlphaBitsCache cache;
  cache.update(scene_a);
  ASSERT_NE(cache.find(a_address), nullptr);
  EXPECT_EQ(cache.find(a_address)->words, AlphaBits::of(*a).words);
  EXPECT_EQ(cache.find(b.get()), nullptr);
  // The scene lets go of the mask: the cache still holds it, so its address cannot be reused.
  a.reset();
  mesh_a.parts.clear();
  EXPECT_FALSE(a_alive.expired());
  Scene scene_b = scene_with(b, mesh_b);
  cache.update(scene_b);
  EXPECT_EQ(cache.find(a_address), nullptr);
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
