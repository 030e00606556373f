#include "ecs/command_buffer.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace silva::ecs {
namespace {

struct Value {
  int v = 0;
};
struct Tag {
  int t = 0;
};

TEST(CommandBuffer, NothingHappensUntilApply) {
  Registry r;
  const Entity e = r.spawn(Value{1});
  CommandBuffer cb;
  cb.spawn(Value{2});
  cb.add(e, Tag{3});
  cb.despawn(e);
  EXPECT_EQ(cb.size(), 4u);  // spawn + its add, add, despawn
  EXPECT_TRUE(r.alive(e));
  EXPECT_FALSE(r.has<Tag>(e));
  EXPECT_EQ(r.entity_count(), 1u);
  cb.apply(r);
  EXPECT_FALSE(r.alive(e));
  EXPECT_EQ(r.entity_count(), 1u);
  EXPECT_TRUE(cb.empty());
}

TEST(CommandBuffer, PendingEntitiesResolveInApplyOrder) {
  Registry r;
  CommandBuffer cb;
  const PendingEntity p0 = cb.spawn(Value{10});
  const PendingEntity p1 = cb.spawn();
  cb.add(p1, Tag{7});
  cb.add(p0, Tag{8});
  Entity seen = null_entity;
  cb.then(p1, [&](Registry& reg, Entity e) {
    seen = e;
    EXPECT_EQ(reg.get<Tag>(e).t, 7);
  });
  const ApplyResult res = cb.apply(r);
  ASSERT_EQ(res.spawned.size(), 2u);
  EXPECT_EQ(res.spawned[p0.slot], (Entity{0, 0}));
  EXPECT_EQ(res.spawned[p1.slot], (Entity{1, 0}));
  EXPECT_EQ(seen, res.spawned[p1.slot]);
  EXPECT_EQ(r.get<Value>(res.spawned[p0.slot]).v, 10);
  EXPECT_EQ(r.get<Tag>(res.spawned[p0.slot]).t, 8);
  EXPECT_FALSE(r.has<Value>(res.spawned[p1.slot]));
}

TEST(CommandBuffer, CommandsOnDeadEntitiesAreSkippedAndCounted) {
  Registry r;
  const Entity e = r.spawn(Value{1});
  CommandBuffer cb;
  cb.despawn(e);
  cb.add(e, Tag{1});
  cb.remove<Value>(e);
  cb.despawn(e);
  EXPECT_EQ(cb.apply(r).skipped, 3u);
}

TEST(CommandBuffer, RemoveAndReplaceApplyInRecordingOrder) {
  Registry r;
  const Entity e = r.spawn(Value{1});
  CommandBuffer cb;
  cb.remove<Value>(e);
  cb.add(e, Value{5});
  cb.add(e, Value{6});
  cb.apply(r);
  EXPECT_EQ(r.get<Value>(e).v, 6);
}

TEST(CommandBuffer, RefusesPendingEntityItDidNotSpawn) {
  CommandBuffer a;
  CommandBuffer b;
  const PendingEntity p = a.spawn();
  EXPECT_THROW(b.add(p, Tag{1}), Error);
}

}  // namespace
}  // namespace silva::ecs
