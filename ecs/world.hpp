#pragma once
/// @file World: a registry plus resources plus a phase scheduler — the ECS entry point.
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "ecs/command_buffer.hpp"
#include "ecs/registry.hpp"
#include "ecs/resources.hpp"
#include "ecs/scheduler.hpp"
#include "ecs/system_builder.hpp"

namespace silva::ecs {

/// Entities, components, resources and systems. Outside run_frame() everything may be
/// changed directly (single-threaded); inside, systems change structure only through
/// command buffers, applied at the end of each phase.
class World : public Registry {
 public:
  /// Stores `value` as the T resource (replacing any); not during run_frame().
  template <class T>
  std::decay_t<T>& set_resource(T&& value) {
    return resources_.set(std::forward<T>(value));
  }
  /// The T resource; throws Error if none was set.
  template <class T>
  T& resource() {
    return resources_.get<T>();
  }
  /// The T resource; throws Error if none was set.
  template <class T>
  const T& resource() const {
    return resources_.get<const T>();
  }
  /// True if a T resource is set.
  template <class T>
  bool has_resource() const {
    return resources_.find<T>() != nullptr;
  }
  /// Starts declaring a system: world.system("move").phase(1).reads<V>().writes<P>().run(fn).
  SystemBuilder system(std::string name) { return SystemBuilder(scheduler_, std::move(name)); }
  /// Every pair of systems that would conflict (empty when the schedule is valid).
  std::vector<ScheduleConflict> schedule_conflicts() const { return scheduler_.conflicts(); }
  /// Validates the schedule now; throws ScheduleError naming conflicting systems.
  void build_schedule() { scheduler_.build(); }
  /// Runs every phase once, in ascending order.
  void run_frame() { scheduler_.run_frame(*this, resources_); }
  /// Runs the phases first..last (inclusive) once, in ascending order: e.g. a setup phase once,
  /// then the per-frame phases every frame.
  template <class E>
  void run_phases(E first, E last) {
    scheduler_.run_phases(static_cast<int>(first), static_cast<int>(last), *this, resources_);
  }
  /// Timing counters of every system, in registration order.
  const std::vector<SystemStats>& system_stats() const { return scheduler_.stats(); }
  /// Zeroes the timing counters.
  void reset_system_stats() { scheduler_.reset_stats(); }
  /// Applies a command buffer now (outside run_frame()).
  ApplyResult apply(CommandBuffer& buffer) { return buffer.apply(*this); }

 private:
  Resources resources_;
  Scheduler scheduler_;
};

}  // namespace silva::ecs
