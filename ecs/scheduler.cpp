#include "ecs/scheduler.hpp"

#include <atomic>
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <unordered_map>

#include <tbb/task_group.h>

#include "ecs/error.hpp"
#include "ecs/system_context.hpp"

namespace silva::ecs {

namespace {

/// "'name' (phase p)" for messages.
std::string describe(const System& s) { return "'" + s.name + "' (phase " + std::to_string(s.phase) + ")"; }

/// Marks in `reach[from]` every node reachable from `node` along `successors`.
void mark_reachable(const std::vector<std::vector<std::size_t>>& successors, std::size_t from, std::size_t node,
                    std::vector<std::vector<bool>>& reach) {
  for (std::size_t next : successors[node]) {
    if (reach[from][next]) continue;
    reach[from][next] = true;
    mark_reachable(successors, from, next, reach);
  }
}

}  // namespace

std::string ScheduleConflict::message() const {
  const char* kind = clash.kind == AccessKind::component ? "component " : "resource ";
  const auto verb = [](bool w) { return w ? "writes" : "reads"; };
  return "ecs: systems '" + first + "' and '" + second + "' in phase " + std::to_string(phase) + " both use " + kind +
         std::string(clash.name) + " ('" + first + "' " + verb(clash.first_writes) + ", '" + second + "' " +
         verb(clash.second_writes) + ") but neither runs after the other; order them with .after()";
}

void Scheduler::add(System system) {
  if (system.name.empty()) throw ScheduleError("ecs: a system needs a non-empty name");
  for (const System& s : systems_) {
    if (s.name == system.name) throw ScheduleError("ecs: system '" + system.name + "' is registered twice");
  }
  if (!system.body) throw ScheduleError("ecs: system '" + system.name + "' has no body");
  stats_.push_back(SystemStats{system.name, system.phase, 0, 0, 0});
  systems_.push_back(std::move(system));
  built_ = false;
}

std::vector<Scheduler::PhasePlan> Scheduler::make_plan() const {
  std::unordered_map<std::string, std::size_t> by_name;
  for (std::size_t i = 0; i < systems_.size(); ++i) by_name.emplace(systems_[i].name, i);
  std::map<int, std::vector<std::size_t>> phases;
  for (std::size_t i = 0; i < systems_.size(); ++i) phases[systems_[i].phase].push_back(i);

  std::vector<PhasePlan> plan;
  for (auto& [phase, members] : phases) {
    PhasePlan p;
    p.phase = phase;
    p.members = members;
    const std::size_t n = members.size();
    std::unordered_map<std::size_t, std::size_t> local;
    for (std::size_t k = 0; k < n; ++k) local.emplace(members[k], k);
    p.successors.assign(n, {});
    p.predecessor_count.assign(n, 0);
    for (std::size_t k = 0; k < n; ++k) {
      const System& s = systems_[members[k]];
      for (const std::string& other : s.after) {
        const auto it = by_name.find(other);
        if (it == by_name.end()) {
          throw ScheduleError("ecs: system " + describe(s) + " runs after '" + other + "', which is not registered");
        }
        const System& o = systems_[it->second];
        if (it->second == members[k]) throw ScheduleError("ecs: system " + describe(s) + " runs after itself");
        if (o.phase > s.phase) {
          throw ScheduleError("ecs: system " + describe(s) + " runs after " + describe(o) + ", a later phase");
        }
        if (o.phase < s.phase) continue;  // earlier phases always finish first
        p.successors[local.at(it->second)].push_back(k);
        ++p.predecessor_count[k];
      }
    }
    // Kahn's algorithm: whatever is never freed lies on an after() cycle.
    std::vector<int> waiting = p.predecessor_count;
    std::vector<std::size_t> ready;
    for (std::size_t k = 0; k < n; ++k) {
      if (waiting[k] == 0) ready.push_back(k);
    }
    std::size_t done = 0;
    while (!ready.empty()) {
      const std::size_t k = ready.back();
      ready.pop_back();
      ++done;
      for (std::size_t s : p.successors[k]) {
        if (--waiting[s] == 0) ready.push_back(s);
      }
    }
    if (done != n) {
      std::string names;
      for (std::size_t k = 0; k < n; ++k) {
        if (waiting[k] > 0) names += (names.empty() ? "'" : ", '") + systems_[members[k]].name + "'";
      }
      throw ScheduleError("ecs: after() cycle in phase " + std::to_string(phase) + " among systems " + names);
    }
    p.reaches.assign(n, std::vector<bool>(n, false));
    for (std::size_t k = 0; k < n; ++k) mark_reachable(p.successors, k, k, p.reaches);
    plan.push_back(std::move(p));
  }
  return plan;
}

std::vector<ScheduleConflict> Scheduler::conflicts_of(const std::vector<PhasePlan>& plan) const {
  std::vector<ScheduleConflict> out;
  for (const PhasePlan& p : plan) {
    for (std::size_t a = 0; a < p.members.size(); ++a) {
      for (std::size_t b = a + 1; b < p.members.size(); ++b) {
        if (p.reaches[a][b] || p.reaches[b][a]) continue;
        const System& sa = systems_[p.members[a]];
        const System& sb = systems_[p.members[b]];
        for (const AccessClash& c : clashes(sa.access, sb.access)) {
          out.push_back(ScheduleConflict{sa.name, sb.name, p.phase, c});
        }
      }
    }
  }
  return out;
}

std::vector<ScheduleConflict> Scheduler::conflicts() const { return conflicts_of(make_plan()); }

void Scheduler::build() {
  std::vector<PhasePlan> plan = make_plan();
  const std::vector<ScheduleConflict> found = conflicts_of(plan);
  if (!found.empty()) {
    std::string message = found.front().message();
    for (std::size_t i = 1; i < found.size(); ++i) {
      message += '\n';
      message += found[i].message();
    }
    throw ScheduleError(message);
  }
  plan_ = std::move(plan);
  built_ = true;
}

void Scheduler::run_frame(Registry& registry, Resources& resources) {
  if (!built_) build();
  for (const PhasePlan& p : plan_) run_phase(p, registry, resources);
}

void Scheduler::run_phases(int first, int last, Registry& registry, Resources& resources) {
  if (!built_) build();
  for (const PhasePlan& p : plan_)
    if (p.phase >= first && p.phase <= last) run_phase(p, registry, resources);
}

void Scheduler::run_phase(const PhasePlan& p, Registry& registry, Resources& resources) {
  const std::size_t n = p.members.size();
  std::vector<std::deque<CommandBuffer>> buffers(n);
  if (n == 1) {
    run_system(p.members[0], registry, resources, buffers[0]);
  } else {
    const auto waiting = std::make_unique<std::atomic<int>[]>(n);
    for (std::size_t k = 0; k < n; ++k) waiting[k].store(p.predecessor_count[k], std::memory_order_relaxed);
    tbb::task_group group;
    std::function<void(std::size_t)> launch = [&](std::size_t k) {
      group.run([&, k] {
        run_system(p.members[k], registry, resources, buffers[k]);
        for (std::size_t s : p.successors[k]) {
          if (waiting[s].fetch_sub(1, std::memory_order_acq_rel) == 1) launch(s);
        }
      });
    };
    for (std::size_t k = 0; k < n; ++k) {
      if (p.predecessor_count[k] == 0) launch(k);
    }
    group.wait();
  }
  for (auto& system_buffers : buffers) {
    for (CommandBuffer& b : system_buffers) b.apply(registry);
  }
}

void Scheduler::run_system(std::size_t index, Registry& registry, Resources& resources,
                           std::deque<CommandBuffer>& buffers) {
  SystemContext context(registry, resources, systems_[index], buffers);
  const auto start = std::chrono::steady_clock::now();
  systems_[index].body(context);
  const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start).count();
  SystemStats& s = stats_[index];
  ++s.calls;
  s.total_ns += static_cast<std::uint64_t>(ns);
  s.last_ns = static_cast<std::uint64_t>(ns);
}

void Scheduler::reset_stats() {
  for (SystemStats& s : stats_) s.calls = s.total_ns = s.last_ns = 0;
}

}  // namespace silva::ecs
