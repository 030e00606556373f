#include "ecs/view.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <set>
#include <vector>

#include "ecs/registry.hpp"

namespace silva::ecs {
namespace {

struct A {
  int v = 0;
};
struct B {
  int v = 0;
};
struct C {
  int v = 0;
};

/// A registry whose entities hold A, B, C by index patterns, scrambled by despawns and
/// removals so the pools' dense orders differ; `with_*` are the brute-force answers.
struct Fixture {
  Registry r;
  std::vector<Entity> all;
  std::set<Entity> with_a, with_ab, with_abc;

  Fixture() {
    for (int i = 0; i < 3000; ++i) {
      const Entity e = r.spawn();
      if (i % 5 != 0) r.add(e, C{i});
      if (i % 3 != 0) r.add(e, B{i});
      if (i % 2 == 0) r.add(e, A{i});
      all.push_back(e);
    }
    for (int i = 0; i < 3000; i += 7) r.despawn(all[i]);
    for (int i = 1; i < 3000; i += 11) r.remove<B>(all[i]);
    for (int i = 0; i < 40; ++i) all.push_back(r.spawn(A{-i}, C{-i}));  // reuses freed slots
    for (const Entity e : all) {
      if (!r.has<A>(e)) continue;  // false for despawned (stale) handles too
      with_a.insert(e);
      if (r.has<B>(e)) with_ab.insert(e);
      if (r.has<B>(e) && r.has<C>(e)) with_abc.insert(e);
    }
  }
};

template <class... Ts>
std::set<Entity> visited(Registry& r) {
  std::set<Entity> seen;
  r.view<Ts...>().each([&](Entity e, Ts&...) { EXPECT_TRUE(seen.insert(e).second) << "visited twice"; });
  return seen;
}

TEST(View, OneTwoAndThreeComponentsSeeExactlyTheMatchingEntities) {
  Fixture f;
  ASSERT_GT(f.with_abc.size(), 100u);
  EXPECT_EQ(visited<A>(f.r), f.with_a);
  EXPECT_EQ(visited<A>(f.r).size(), f.r.pool<A>().size());
  EXPECT_EQ((visited<A, B>(f.r)), f.with_ab);
  EXPECT_EQ((visited<B, A>(f.r)), f.with_ab);
  EXPECT_EQ((visited<A, B, C>(f.r)), f.with_abc);
  EXPECT_EQ((visited<C, const B, A>(f.r)), f.with_abc);
}

TEST(View, PassesTheComponentsOfTheVisitedEntity) {
  Fixture f;
  f.r.view<const A, B, const C>().each([&](Entity e, const A& a, B& b, const C& c) {
    EXPECT_EQ(a.v, f.r.get<A>(e).v);
    EXPECT_EQ(&b, &f.r.get<B>(e));
    EXPECT_EQ(c.v, f.r.get<C>(e).v);
  });
}

TEST(View, CallbackWithoutEntityAndWritesThroughReferences) {
  Registry r;
  for (int i = 0; i < 10; ++i) r.spawn(A{i}, B{1});
  r.view<A, const B>().each([](A& a, const B& b) { a.v += b.v; });
  int sum = 0;
  r.view<const A>().each([&](const A& a) { sum += a.v; });
  EXPECT_EQ(sum, 45 + 10);
}

TEST(View, TypeNeverStoredGivesEmptyView) {
  Registry r;
  r.spawn(A{1});
  int calls = 0;
  r.view<A, C>().each([&](A&, C&) { ++calls; });
  EXPECT_EQ(calls, 0);
  EXPECT_EQ((r.view<A, C>().size_hint()), 0u);
}

TEST(View, DrivesIterationByTheSmallestPool) {
  Registry r;
  for (int i = 0; i < 100; ++i) r.spawn(A{i});
  const Entity e = r.spawn(A{1}, B{2});
  EXPECT_EQ((r.view<A, B>().size_hint()), 1u);
  EXPECT_TRUE((r.view<A, B>().contains(e)));
}

TEST(View, ChunksCoverTheDenseRangeWithFixedBoundaries) {
  Fixture f;
  const auto v = f.r.view<A, B>();
  const std::size_t chunk = 64;
  EXPECT_EQ(v.chunk_count(chunk), (v.size_hint() + chunk - 1) / chunk);
  std::set<Entity> seen;
  for (std::size_t c = 0; c < v.chunk_count(chunk); ++c) {
    v.each_in_chunk(c, chunk, [&](Entity e, A&, B&) { EXPECT_TRUE(seen.insert(e).second); });
  }
  EXPECT_EQ(seen, f.with_ab);
  EXPECT_THROW(v.chunk_count(0), Error);
}

TEST(View, ParallelEachTouchesEveryEntityExactlyOnce) {
  Registry r;
  std::vector<Entity> es;
  for (int i = 0; i < 20000; ++i) es.push_back(r.spawn(A{0}, B{i}));
  for (int threads : {1, 2}) {
    tbb::task_arena arena(threads);
    arena.execute([&] {
      r.view<A, const B>().parallel_each([](A& a, const B&) { ++a.v; }, 97);
    });
  }
  for (const Entity e : es) ASSERT_EQ(r.get<A>(e).v, 2) << to_string(e);
  std::atomic<int> calls{0};
  r.view<A>().parallel_each([&](A&) { calls.fetch_add(1, std::memory_order_relaxed); });
  EXPECT_EQ(calls.load(), 20000);
}

}  // namespace
}  // namespace silva::ecs
