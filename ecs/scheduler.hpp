#pragma once
/// @file The phase scheduler: validates system accesses and runs phases in order, with
/// non-conflicting systems of a phase running concurrently on TBB.
#include <cstddef>
#include <deque>
#include <string>
#include <vector>

#include "ecs/access.hpp"
#include "ecs/command_buffer.hpp"
#include "ecs/fwd.hpp"
#include "ecs/registry.hpp"
#include "ecs/resources.hpp"
#include "ecs/system.hpp"

namespace silva::ecs {

/// Two systems of one phase that touch the same type, one of them writing, with neither
/// ordered after the other (directly or through a chain of after()).
struct ScheduleConflict {
  std::string first;   ///< The earlier-registered system.
  std::string second;  ///< The later-registered system.
  int phase = 0;       ///< Their common phase.
  AccessClash clash;   ///< The shared type and who writes it.
  /// One line naming both systems, the type and how to resolve it.
  std::string message() const;
};

/// Holds systems and runs frames. Within a phase, a system starts once every system it
/// runs after has finished; unordered systems run concurrently. At the end of each phase
/// the command buffers are applied by system registration order, then buffer order.
class Scheduler {
 public:
  /// Adds a system; throws ScheduleError for an empty or duplicate name.
  void add(System system);
  /// Every conflicting pair, in registration order; throws ScheduleError on bad after().
  std::vector<ScheduleConflict> conflicts() const;
  /// Validates the schedule; throws ScheduleError listing every conflict or ordering error.
  void build();
  /// Runs every phase once in ascending order (building first if systems changed).
  void run_frame(Registry& registry, Resources& resources);
  /// Runs the phases numbered first..last (inclusive) once, in ascending order.
  void run_phases(int first, int last, Registry& registry, Resources& resources);
  /// Timing counters of every system, in registration order.
  const std::vector<SystemStats>& stats() const { return stats_; }
  /// Zeroes every timing counter.
  void reset_stats();

 private:
  struct PhasePlan {
    int phase = 0;
    std::vector<std::size_t> members;                  // system indices, registration order
    std::vector<std::vector<std::size_t>> successors;  // local index -> local indices after it
    std::vector<int> predecessor_count;                // local index -> direct predecessors
    std::vector<std::vector<bool>> reaches;            // [a][b]: b runs (transitively) after a
  };

  std::vector<PhasePlan> make_plan() const;
  std::vector<ScheduleConflict> conflicts_of(const std::vector<PhasePlan>& plan) const;
  void run_phase(const PhasePlan& phase, Registry& registry, Resources& resources);
  void run_system(std::size_t index, Registry& registry, Resources& resources, std::deque<CommandBuffer>& buffers);

  std::vector<System> systems_;
  std::vector<SystemStats> stats_;
  std::vector<PhasePlan> plan_;
  bool built_ = false;
};

}  // namespace silva::ecs
