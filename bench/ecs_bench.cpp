/// @file ECS micro-benchmarks: SoA view iteration vs a pointer-chasing baseline, parallel
/// chunked iteration at 1 and 2 threads, spawn/despawn throughput, per-frame scheduler cost.
#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ecs/world.hpp"

namespace {

using silva::ecs::CommandBuffer;
using silva::ecs::Entity;
using silva::ecs::Registry;
using silva::ecs::SystemContext;
using silva::ecs::World;

struct Position {
  float x, y, z;
};
struct Velocity {
  float x, y, z;
};
struct Acceleration {
  float x, y, z;
};

constexpr std::size_t kEntities = 1'000'000;
constexpr std::size_t kChurn = 100'000;
constexpr float kDt = 1.0f / 60.0f;

/// The naive baseline: one heap object per entity, each component in its own allocation.
struct NaiveObject {
  std::unique_ptr<Position> position;
  std::unique_ptr<Velocity> velocity;
  std::unique_ptr<Acceleration> acceleration;
};

/// A registry of `n` entities with Position, Velocity and (if `with_acceleration`) Acceleration.
std::unique_ptr<Registry> make_registry(std::size_t n, bool with_acceleration) {
  auto r = std::make_unique<Registry>();
  r->pool<Position>().reserve(n);
  r->pool<Velocity>().reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const float f = float(i % 1000);
    const Entity e = r->spawn(Position{f, 0, 0}, Velocity{1, f, 2});
    if (with_acceleration) r->add(e, Acceleration{0, 0, -9.81f});
  }
  return r;
}

/// `n` naive objects (acceleration optional); with `scattered` the pointer array visits them in a fixed stride
/// permutation, as after churn (allocation order no longer matches iteration order).
std::vector<NaiveObject*> make_naive(std::size_t n, bool scattered, bool with_acceleration,
                                      std::vector<std::unique_ptr<NaiveObject>>& owner) {
  owner.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const float f = float(i % 1000);
    auto o = std::make_unique<NaiveObject>();
    o->position = std::make_unique<Position>(Position{f, 0, 0});
    o->velocity = std::make_unique<Velocity>(Velocity{1, f, 2});
    if (with_acceleration) o->acceleration = std::make_unique<Acceleration>(Acceleration{0, 0, -9.81f});
    owner.push_back(std::move(o));
  }
  std::vector<NaiveObject*> objects(n);
  constexpr std::size_t kStride = 7919;  // prime, coprime with 10^6
  for (std::size_t i = 0; i < n; ++i) objects[i] = owner[scattered ? (i * kStride) % n : i].get();
  return objects;
}

void integrate(Position& p, const Velocity& v) {
  p.x += v.x * kDt;
  p.y += v.y * kDt;
  p.z += v.z * kDt;
}

void accelerate(Velocity& v, const Acceleration& a) {
  v.x += a.x * kDt;
  v.y += a.y * kDt;
  v.z += a.z * kDt;
}

void BM_EcsIterate2(benchmark::State& state) {
  auto r = make_registry(kEntities, false);
  for (auto _ : state) {
    r->view<Position, const Velocity>().each([](Position& p, const Velocity& v) { integrate(p, v); });
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(kEntities));
  state.counters["entities"] = double(kEntities);
}

void BM_NaiveIterate2(benchmark::State& state) {
  std::vector<std::unique_ptr<NaiveObject>> owner;
  const auto objects = make_naive(kEntities, state.range(0) != 0, false, owner);
  for (auto _ : state) {
    for (NaiveObject* o : objects) integrate(*o->position, *o->velocity);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(kEntities));
  state.counters["entities"] = double(kEntities);
}

void BM_EcsIterate3(benchmark::State& state) {
  auto r = make_registry(kEntities, true);
  for (auto _ : state) {
    r->view<Position, Velocity, const Acceleration>().each([](Position& p, Velocity& v, const Acceleration& a) {
      accelerate(v, a);
      integrate(p, v);
    });
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(kEntities));
  state.counters["entities"] = double(kEntities);
}

void BM_NaiveIterate3(benchmark::State& state) {
  std::vector<std::unique_ptr<NaiveObject>> owner;
  const auto objects = make_naive(kEntities, state.range(0) != 0, true, owner);
  for (auto _ : state) {
    for (NaiveObject* o : objects) {
      accelerate(*o->velocity, *o->acceleration);
      integrate(*o->position, *o->velocity);
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(kEntities));
  state.counters["entities"] = double(kEntities);
}

/// Chunked parallel iteration (4096-entity chunks) in an arena of range(0) threads.
void BM_EcsParallelIterate2(benchmark::State& state) {
  auto r = make_registry(kEntities, false);
  tbb::task_arena arena(int(state.range(0)));
  for (auto _ : state) {
    arena.execute([&] {
      r->view<Position, const Velocity>().parallel_each([](Position& p, const Velocity& v) { integrate(p, v); });
    });
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(kEntities));
  state.counters["threads"] = double(state.range(0));
}

void BM_EcsSpawnDespawn(benchmark::State& state) {
  Registry r;
  std::vector<Entity> es(kChurn);
  for (auto _ : state) {
    for (std::size_t i = 0; i < kChurn; ++i) es[i] = r.spawn(Position{1, 2, 3}, Velocity{4, 5, 6});
    for (const Entity e : es) r.despawn(e);
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(kChurn));
}

void BM_NaiveSpawnDespawn(benchmark::State& state) {
  std::vector<std::unique_ptr<NaiveObject>> objects(kChurn);
  for (auto _ : state) {
    for (auto& o : objects) {
      o = std::make_unique<NaiveObject>();
      o->position = std::make_unique<Position>(Position{1, 2, 3});
      o->velocity = std::make_unique<Velocity>(Velocity{4, 5, 6});
    }
    for (auto& o : objects) o.reset();
    benchmark::DoNotOptimize(objects.data());
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(kChurn));
}

/// Spawn through a command buffer (record, then apply), then despawn through another.
void BM_EcsCommandBufferSpawnDespawn(benchmark::State& state) {
  Registry r;
  for (auto _ : state) {
    CommandBuffer spawns;
    for (std::size_t i = 0; i < kChurn; ++i) spawns.spawn(Position{1, 2, 3}, Velocity{4, 5, 6});
    const auto applied = spawns.apply(r);
    CommandBuffer despawns;
    for (const Entity e : applied.spawned) despawns.despawn(e);
    despawns.apply(r);
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(kChurn));
}

/// One frame of 8 trivial systems in 4 phases: the scheduler's fixed per-frame cost.
void BM_SchedulerEmptyFrame(benchmark::State& state) {
  struct A {};
  struct B {};
  World w;
  for (int phase = 0; phase < 4; ++phase) {
    const std::string p = std::to_string(phase);
    w.system("read_a" + p).phase(phase).reads<A>().run([](SystemContext&) {});
    w.system("write_b" + p).phase(phase).writes<B>().run([](SystemContext&) {});
  }
  tbb::task_arena arena(2);
  for (auto _ : state) arena.execute([&] { w.run_frame(); });
  state.SetItemsProcessed(std::int64_t(state.iterations()));
}

/// A whole frame through the scheduler: integrate 1 M entities in a parallel_each system.
void BM_SchedulerIntegrateFrame(benchmark::State& state) {
  World w;
  for (std::size_t i = 0; i < kEntities; ++i) w.spawn(Position{float(i % 1000), 0, 0}, Velocity{1, 2, 3});
  w.system("integrate").parallel_each<Position, const Velocity>([](Position& p, const Velocity& v) { integrate(p, v); });
  tbb::task_arena arena(int(state.range(0)));
  for (auto _ : state) arena.execute([&] { w.run_frame(); });
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(kEntities));
  state.counters["threads"] = double(state.range(0));
  state.counters["system_last_ms"] = double(w.system_stats()[0].last_ns) * 1e-6;
}

}  // namespace

BENCHMARK(BM_EcsIterate2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NaiveIterate2)->ArgName("scattered")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EcsIterate3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NaiveIterate3)->ArgName("scattered")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EcsParallelIterate2)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_EcsSpawnDespawn)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NaiveSpawnDespawn)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EcsCommandBufferSpawnDespawn)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SchedulerEmptyFrame)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(BM_SchedulerIntegrateFrame)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
