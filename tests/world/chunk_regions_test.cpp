#include "world/chunk_regions.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace silva::world {

TEST(ChunkRegions, DefaultWorldIsEveryChunkWithinRenderDistance) {
  const Config cfg;  // extent 512, render distance 250, chunk 32
  const auto chunks = default_world_chunks(cfg);
  // Rounded square of area 512^2 + 4*512*250 + pi*250^2 = 970 494 m^2 ~ 948 chunks, plus the rim.
  EXPECT_GT(chunks.size(), 948u);
  EXPECT_LT(chunks.size(), 1100u);
  EXPECT_TRUE(std::is_sorted(chunks.begin(), chunks.end()));
  // The capture square spans chunks -8..7 on both axes.
  const auto has = [&](ChunkCoord c) { return std::find(chunks.begin(), chunks.end(), c) != chunks.end(); };
  EXPECT_TRUE(has(ChunkCoord{-8, -8}));
  EXPECT_TRUE(has(ChunkCoord{7, 15}));    // starts 224 m above the square's top edge
  EXPECT_FALSE(has(ChunkCoord{7, 16}));   // starts 256 m above: beyond 250 m
  EXPECT_FALSE(has(ChunkCoord{14, 14}));  // diagonal gap sqrt(2)*192 = 271 m
}

TEST(ChunkRegions, DiscKnownAnswer) {
  // A disc of radius 16 centred on a chunk corner touches exactly the 4 chunks at that corner.
  const auto c = chunks_in_disc(32, 32, 16, 32);
  EXPECT_EQ(c, (std::vector<ChunkCoord>{{0, 0}, {0, 1}, {1, 0}, {1, 1}}));
}

TEST(ChunkRegions, ViewFrustumChunks) {
  Camera cam = Camera::from_fov(640, 480, 90, 0.05, 100);
  cam.camera_to_world = pose_from_angles(Vec3d(16, 16, 1.5), 0, 0, 0);  // looks along +X
  const auto c = chunks_in_view(cam, 32);
  // Everything ahead up to x = 116, within |y - 16| <= 100; nothing behind the camera.
  for (ChunkCoord k : c) {
    EXPECT_GE(k.i, 0);
    EXPECT_LE(k.i, 3);
  }
  EXPECT_NE(std::find(c.begin(), c.end(), ChunkCoord{3, 0}), c.end());
  EXPECT_NE(std::find(c.begin(), c.end(), ChunkCoord{0, 0}), c.end());
  EXPECT_EQ(std::find(c.begin(), c.end(), ChunkCoord{-1, 0}), c.end());
  // The horizontal footprint is a triangle-ish wedge: a chunk far to the side near the camera is out.
  EXPECT_EQ(std::find(c.begin(), c.end(), ChunkCoord{0, 3}), c.end());
  EXPECT_NE(std::find(c.begin(), c.end(), ChunkCoord{3, 3}), c.end());
}

}  // namespace silva::world
