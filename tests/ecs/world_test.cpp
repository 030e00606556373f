#include "ecs/world.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cstdint>
#include <vector>

namespace silva::ecs {
namespace {

struct Value {
  std::int64_t v = 0;
};
struct Tag {
  std::int64_t t = 0;
};
struct Frame {
  int n = 0;
};

/// Everything observable about a world: live entities and component arrays in dense order.
struct Snapshot {
  std::size_t live = 0;
  std::vector<std::uint64_t> value_entities, tag_entities;
  std::vector<std::int64_t> values, tags;
  bool operator==(const Snapshot&) const = default;
};

Snapshot snapshot(World& w) {
  Snapshot s;
  s.live = w.entity_count();
  for (const Entity e : w.pool<Value>().entities()) s.value_entities.push_back(e.bits());
  for (const Value& v : w.pool<Value>().components()) s.values.push_back(v.v);
  for (const Entity e : w.pool<Tag>().entities()) s.tag_entities.push_back(e.bits());
  for (const Tag& t : w.pool<Tag>().components()) s.tags.push_back(t.t);
  return s;
}

/// Runs three frames of a world whose parallel system spawns, despawns, tags and untags
/// from many chunks at once, inside an arena of `threads` threads.
Snapshot run_churn(int threads) {
  World w;
  for (int i = 0; i < 20000; ++i) w.spawn(Value{i});
  w.set_resource(Frame{0});
  w.system("churn").reads_resource<Frame>().parallel_each<const Value>(
      [&w](CommandBuffer& cb, Entity e, const Value& v) {
        const std::int64_t x = v.v + w.resource<Frame>().n;
        if (x % 3 == 0) {
          const PendingEntity child = cb.spawn(Value{x * 2 + 1});
          if (x % 9 == 0) cb.add(child, Tag{x});
        }
        if (x % 5 == 0) cb.despawn(e);
        if (x % 7 == 0) cb.add(e, Tag{-x});
        if (x % 11 == 0) cb.remove<Tag>(e);
      },
      256);
  w.system("tick").phase(1).writes_resource<Frame>().run([](SystemContext& ctx) { ++ctx.resource<Frame>().n; });
  tbb::task_arena arena(threads);
  arena.execute([&] {
    for (int f = 0; f < 3; ++f) w.run_frame();
  });
  return snapshot(w);
}

TEST(World, CommandBufferApplicationIsTheSameForOneAndTwoThreads) {
  const Snapshot one = run_churn(1);
  const Snapshot two = run_churn(2);
  EXPECT_GT(one.tags.size(), 1000u);
  EXPECT_NE(one.live, 20000u);
  EXPECT_TRUE(one == two) << "live " << one.live << " vs " << two.live;
  EXPECT_TRUE(run_churn(2) == two);
}

TEST(World, ChunkCommandBuffersApplyInChunkOrder) {
  World w;
  for (int i = 0; i < 1000; ++i) w.spawn(Value{i});
  w.system("clone").parallel_each<const Value>(
      [](CommandBuffer& cb, Entity, const Value& v) { cb.spawn(Tag{v.v}); }, 10);
  tbb::task_arena arena(2);
  arena.execute([&] { w.run_frame(); });
  const auto tags = w.pool<Tag>().components();
  ASSERT_EQ(tags.size(), 1000u);
  for (std::size_t i = 0; i < tags.size(); ++i) ASSERT_EQ(tags[i].t, std::int64_t(i));
}

TEST(World, ParallelEachSystemTouchesEveryEntityExactlyOnce) {
  World w;
  for (int i = 0; i < 10007; ++i) w.spawn(Value{0}, Tag{i});
  w.system("bump").parallel_each<Value, const Tag>([](Value& v, const Tag&) { ++v.v; }, 100);
  tbb::task_arena arena(2);
  arena.execute([&] { w.run_frame(); });
  for (const Value& v : w.pool<Value>().components()) ASSERT_EQ(v.v, 1);
}

TEST(World, ResourcesAndDirectApply) {
  World w;
  EXPECT_FALSE(w.has_resource<Frame>());
  w.set_resource(Frame{4});
  EXPECT_EQ(w.resource<Frame>().n, 4);
  EXPECT_THROW(w.resource<Tag>(), Error);
  CommandBuffer cb;
  cb.spawn(Value{1});
  EXPECT_EQ(w.apply(cb).spawned.size(), 1u);
  EXPECT_EQ(w.entity_count(), 1u);
}

}  // namespace
}  // namespace silva::ecs
