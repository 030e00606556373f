// world_hash against the byte layout it documents, fed to XXH3 piece by piece here; summarise_world's counts.
#include "world/world_summary.hpp"

#include <gtest/gtest.h>
#include <xxhash.h>

#include <vector>

namespace silva::world {
namespace {

/// Two chunks with a small terrain mesh (one part with an overlay) and three objects.
std::vector<ChunkContent> sample_chunks() {
  std::vector<ChunkContent> chunks(2);
  for (int k = 0; k < 2; ++k) {
    ChunkContent& c = chunks[size_t(k)];
    c.coord = ChunkCoord{k - 1, 2 * k};
    c.terrain.positions = {Vec3f(0.5f, 1.25f, -3.0f), Vec3f(2.0f + float(k), 0.0f, 7.5f), Vec3f(-1.0f, 4.0f, 0.125f)};
    c.terrain.normals = {Vec3f(0, 0, 1), Vec3f(0.6f, 0, 0.8f), Vec3f(0, -0.6f, 0.8f)};
    c.terrain.uvs = {Vec2f(0.1f, 0.2f), Vec2f(-0.5f, 3.0f), Vec2f(1.0f, 0.0f)};
    c.terrain.indices = {0, 1, 2};
    MeshPart part;
    part.index_count = 3;
    part.role = Role::Ground;
    part.material = Material::Ground;
    if (k == 1) part.overlay = PartOverlay{Role::Trail, Material::Trail};
    c.terrain.parts.push_back(part);
  }
  chunks[0].objects.push_back({7, Role::TreeTrunk, Placement::Correct, Vec3f(1, 2, 3), 0.5f, 1.25f, 42});
  chunks[0].objects.push_back({3, Role::Obstacle, Placement::Adjusted, Vec3f(-4, 5, 6), 2.0f, 0.75f, 43});
  chunks[1].objects.push_back({7, Role::GroundVegetation, Placement::Correct, Vec3f(9, 8, 7), 1.0f, 1.0f, 0});
  return chunks;
}

/// The documented layout fed one coefficient group at a time, as an independent reference.
uint64_t reference_hash(const std::vector<ChunkContent>& chunks) {
  XXH3_state_t* st = XXH3_createState();
  XXH3_64bits_reset(st);
  const auto feed3 = [&](const std::vector<Vec3f>& v) {
    const uint64_t n = v.size();
    XXH3_64bits_update(st, &n, sizeof n);
    for (const Vec3f& x : v) {
      const float f[3] = {x.x(), x.y(), x.z()};
      XXH3_64bits_update(st, f, sizeof f);
    }
  };
  for (const ChunkContent& c : chunks) {
    const int32_t ij[2] = {c.coord.i, c.coord.j};
    XXH3_64bits_update(st, ij, sizeof ij);
    feed3(c.terrain.positions);
    feed3(c.terrain.normals);
    const uint64_t n = c.terrain.uvs.size();
    XXH3_64bits_update(st, &n, sizeof n);
    for (const Vec2f& uv : c.terrain.uvs) {
      const float f[2] = {uv.x(), uv.y()};
      XXH3_64bits_update(st, f, sizeof f);
    }
    XXH3_64bits_update(st, c.terrain.indices.data(), c.terrain.indices.size() * sizeof(uint32_t));
    for (const MeshPart& p : c.terrain.parts) {
      const uint32_t overlay = p.overlay ? 1u << 16 | uint32_t(p.overlay->role) << 8 | uint32_t(p.overlay->material) : 0u;
      const uint32_t w[5] = {p.first_index, p.index_count, uint32_t(p.role), uint32_t(p.material), overlay};
      XXH3_64bits_update(st, w, sizeof w);
    }
    for (const Vegetation& v : c.objects) {
      const uint32_t w[4] = {v.asset, uint32_t(v.role), uint32_t(v.placement), v.instance_id};
      const float f[5] = {v.position.x(), v.position.y(), v.position.z(), v.yaw, v.scale};
      XXH3_64bits_update(st, w, sizeof w);
      XXH3_64bits_update(st, f, sizeof f);
    }
  }
  const uint64_t h = XXH3_64bits_digest(st);
  XXH3_freeState(st);
  return h;
}

TEST(WorldSummary, HashIsTheDocumentedByteLayout) {
  const std::vector<ChunkContent> chunks = sample_chunks();
  EXPECT_EQ(world_hash(chunks), reference_hash(chunks));
  EXPECT_EQ(chunk_hash(chunks[1]), reference_hash({chunks[1]}));
  std::vector<ChunkContent> moved = chunks;
  moved[1].objects[0].position.z() += 0.001f;
  EXPECT_NE(world_hash(moved), world_hash(chunks));
}

TEST(WorldSummary, CountsDistinctAssetsAndSortsChunks) {
  std::vector<ChunkContent> chunks = sample_chunks();
  std::swap(chunks[0], chunks[1]);
  const BuiltWorld w = summarise_world(chunks);
  EXPECT_EQ(w.totals.distinct_assets, 2u);  // assets 7 and 3
  ASSERT_EQ(w.chunks.size(), 2u);
  EXPECT_EQ(w.chunks[0].coord.i, -1);
  EXPECT_EQ(w.hash, reference_hash(sample_chunks()));
}

}  // namespace
}  // namespace silva::world
