#include "ecs/entity_allocator.hpp"

#include <gtest/gtest.h>

namespace silva::ecs {
namespace {

TEST(EntityAllocator, HandsOutSequentialIndicesAtGenerationZero) {
  EntityAllocator a;
  EXPECT_EQ(a.create(), (Entity{0, 0}));
  EXPECT_EQ(a.create(), (Entity{1, 0}));
  EXPECT_EQ(a.live_count(), 2u);
}

TEST(EntityAllocator, ReusedSlotGetsNewGenerationAndOldHandleIsStale) {
  EntityAllocator a;
  const Entity first = a.create();
  ASSERT_TRUE(a.destroy(first));
  const Entity second = a.create();
  EXPECT_EQ(second.index, first.index);
  EXPECT_EQ(second.generation, first.generation + 1);
  EXPECT_FALSE(a.alive(first));
  EXPECT_TRUE(a.alive(second));
  EXPECT_NE(first, second);
}

TEST(EntityAllocator, DestroyingTwiceOrNullIsRefused) {
  EntityAllocator a;
  const Entity e = a.create();
  EXPECT_TRUE(a.destroy(e));
  EXPECT_FALSE(a.destroy(e));
  EXPECT_FALSE(a.destroy(null_entity));
  EXPECT_FALSE(a.alive(null_entity));
  EXPECT_EQ(a.live_count(), 0u);
}

TEST(EntityAllocator, FreedSlotsAreReusedLastFreedFirst) {
  EntityAllocator a;
  const Entity e0 = a.create();
  const Entity e1 = a.create();
  a.create();
  a.destroy(e0);
  a.destroy(e1);
  EXPECT_EQ(a.create().index, e1.index);
  EXPECT_EQ(a.create().index, e0.index);
  EXPECT_EQ(a.create().index, 3u);
}

TEST(Entity, ToStringNamesIndexAndGeneration) {
  EXPECT_EQ(to_string(Entity{5, 2}), "#5.v2");
  EXPECT_EQ(to_string(null_entity), "null");
}

}  // namespace
}  // namespace silva::ecs
