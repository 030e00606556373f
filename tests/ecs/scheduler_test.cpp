#include "ecs/scheduler.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "ecs/world.hpp"

namespace silva::ecs {
namespace {

struct Pos {
  int v = 0;
};
struct Vel {
  int v = 0;
};
struct Counter {
  int n = 0;
};

/// Thread-safe record of which systems ran, in order.
struct Log {
  std::mutex m;
  std::vector<std::string> names;
  void add(const std::string& s) {
    std::lock_guard lock(m);
    names.push_back(s);
  }
};

/// Sets `mine`, then waits up to 2 s for `theirs`; true if both were up at once.
bool meet(std::atomic<bool>& mine, const std::atomic<bool>& theirs) {
  mine.store(true);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  while (!theirs.load()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::yield();
  }
  return true;
}

TEST(Scheduler, NonConflictingSystemsOfAPhaseRunConcurrently) {
  bool overlapped = false;
  for (int attempt = 0; attempt < 5 && !overlapped; ++attempt) {
    std::atomic<bool> a_up{false}, b_up{false}, a_met{false}, b_met{false};
    World w;
    w.system("a").reads<Pos>().run([&](SystemContext&) { a_met = meet(a_up, b_up); });
    w.system("b").reads<Pos>().writes<Vel>().run([&](SystemContext&) { b_met = meet(b_up, a_up); });
    tbb::task_arena arena(2);
    arena.execute([&] { w.run_frame(); });
    overlapped = a_met && b_met;
  }
  EXPECT_TRUE(overlapped) << "systems a and b never ran at the same time in a 2-thread arena";
}

TEST(Scheduler, RefusesTwoWritersOfOneComponentNamingBoth) {
  World w;
  w.system("integrate").phase(1).writes<Pos>().run([](SystemContext&) {});
  w.system("snap").phase(1).writes<Pos>().run([](SystemContext&) {});
  try {
    w.run_frame();
    FAIL() << "conflicting systems must be refused";
  } catch (const ScheduleError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("'integrate'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("'snap'"), std::string::npos) << msg;
    EXPECT_NE(msg.find(std::string(type_name<Pos>())), std::string::npos) << msg;
  }
}

TEST(Scheduler, ReportsAmbiguousReadWritePairsIncludingResources) {
  World w;
  w.system("reader").reads<Pos>().reads_resource<Counter>().run([](SystemContext&) {});
  w.system("writer").writes<Pos>().run([](SystemContext&) {});
  w.system("tally").writes_resource<Counter>().run([](SystemContext&) {});
  w.system("elsewhere").phase(2).writes<Pos>().writes_resource<Counter>().run([](SystemContext&) {});
  const auto found = w.schedule_conflicts();
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].first, "reader");
  EXPECT_EQ(found[0].second, "writer");
  EXPECT_EQ(found[0].clash.kind, AccessKind::component);
  EXPECT_FALSE(found[0].clash.first_writes);
  EXPECT_TRUE(found[0].clash.second_writes);
  EXPECT_EQ(found[1].first, "reader");
  EXPECT_EQ(found[1].second, "tally");
  EXPECT_EQ(found[1].clash.kind, AccessKind::resource);
  EXPECT_THROW(w.build_schedule(), ScheduleError);
}

TEST(Scheduler, ReadersOfOneComponentDoNotConflict) {
  World w;
  w.system("r1").reads<Pos>().run([](SystemContext&) {});
  w.system("r2").reads<Pos>().run([](SystemContext&) {});
  EXPECT_TRUE(w.schedule_conflicts().empty());
  EXPECT_NO_THROW(w.run_frame());
}

TEST(Scheduler, OrderedPairRunsOneAfterTheOther) {
  for (int attempt = 0; attempt < 20; ++attempt) {
    World w;
    std::atomic<bool> first_done{false};
    std::atomic<bool> second_saw_first{false};
    // registered in reverse so registration order cannot explain the result
    w.system("second").writes<Pos>().after("first").run([&](SystemContext&) { second_saw_first = first_done.load(); });
    w.system("first").writes<Pos>().run([&](SystemContext&) {
      std::this_thread::yield();
      first_done = true;
    });
    EXPECT_TRUE(w.schedule_conflicts().empty());
    tbb::task_arena arena(2);
    arena.execute([&] { w.run_frame(); });
    ASSERT_TRUE(second_saw_first.load()) << "attempt " << attempt;
  }
}

TEST(Scheduler, OrderingIsTransitive) {
  World w;
  Log log;
  w.system("c").writes<Pos>().after("b").run([&](SystemContext&) { log.add("c"); });
  w.system("b").reads<Vel>().after("a").run([&](SystemContext&) { log.add("b"); });
  w.system("a").writes<Pos>().run([&](SystemContext&) { log.add("a"); });
  EXPECT_TRUE(w.schedule_conflicts().empty());
  w.run_frame();
  EXPECT_EQ(log.names, (std::vector<std::string>{"a", "b", "c"}));
}

TEST(Scheduler, PhasesRunInAscendingOrderWithCommandsAppliedBetween) {
  World w;
  Log log;
  w.system("late").phase(5).reads<Pos>().run([&](SystemContext& ctx) {
    int n = 0;
    ctx.view<const Pos>().each([&](const Pos&) { ++n; });
    log.add("late saw " + std::to_string(n));
  });
  w.system("early").phase(-1).run([&](SystemContext& ctx) {
    log.add("early");
    ctx.commands().spawn(Pos{1});
  });
  w.system("middle").phase(2).run([&](SystemContext& ctx) {
    log.add("middle");
    ctx.commands().spawn(Pos{2});
  });
  w.run_frame();
  EXPECT_EQ(log.names, (std::vector<std::string>{"early", "middle", "late saw 2"}));
}

TEST(Scheduler, RefusesBadOrdering) {
  {
    World w;
    w.system("a").after("ghost").run([](SystemContext&) {});
    EXPECT_THROW(w.build_schedule(), ScheduleError);
  }
  {
    World w;
    w.system("a").after("b").run([](SystemContext&) {});
    w.system("b").after("a").run([](SystemContext&) {});
    EXPECT_THROW(w.build_schedule(), ScheduleError);
  }
  {
    World w;
    w.system("a").phase(0).after("b").run([](SystemContext&) {});
    w.system("b").phase(1).run([](SystemContext&) {});
    EXPECT_THROW(w.build_schedule(), ScheduleError);
  }
  {
    World w;
    w.system("a").run([](SystemContext&) {});
    EXPECT_THROW(w.system("a").run([](SystemContext&) {}), ScheduleError);
  }
}

TEST(Scheduler, AfterASystemOfAnEarlierPhaseIsAllowed) {
  World w;
  w.system("a").phase(0).writes<Pos>().run([](SystemContext&) {});
  w.system("b").phase(1).writes<Pos>().after("a").run([](SystemContext&) {});
  EXPECT_NO_THROW(w.build_schedule());
}

TEST(Scheduler, CountsCallsPerSystem) {
  World w;
  w.system("a").run([](SystemContext&) {});
  w.system("b").phase(3).run([](SystemContext&) {});
  for (int i = 0; i < 3; ++i) w.run_frame();
  const auto& stats = w.system_stats();
  ASSERT_EQ(stats.size(), 2u);
  EXPECT_EQ(stats[0].name, "a");
  EXPECT_EQ(stats[1].phase, 3);
  EXPECT_EQ(stats[0].calls, 3u);
  EXPECT_EQ(stats[1].calls, 3u);
  EXPECT_GE(stats[0].total_ns, stats[0].last_ns);
  w.reset_system_stats();
  EXPECT_EQ(w.system_stats()[0].calls, 0u);
}

TEST(Scheduler, ExceptionFromASystemReachesTheCaller) {
  World w;
  w.system("a").run([](SystemContext&) { throw std::runtime_error("boom"); });
  w.system("b").run([](SystemContext&) {});
  EXPECT_THROW(w.run_frame(), std::runtime_error);
}

}  // namespace
}  // namespace silva::ecs
