#pragma once
/// @file A system: a named function with a phase, declared accesses and ordering constraints.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "ecs/access.hpp"
#include "ecs/fwd.hpp"

namespace silva::ecs {

/// Everything the scheduler knows about one system.
struct System {
  std::string name;                          ///< Unique name, used in messages and after().
  int phase = 0;                             ///< Phases run in ascending order.
  Access access;                             ///< Declared component/resource reads and writes.
  std::vector<std::string> after;            ///< Systems this one must run after.
  std::function<void(SystemContext&)> body;  ///< The work, called once per frame.
};

/// Timing counters of one system, for benchmarks and progress reports.
struct SystemStats {
  std::string name;          ///< The system's name.
  int phase = 0;             ///< The system's phase.
  std::uint64_t calls = 0;     ///< Frames the system ran in.
  std::uint64_t total_ns = 0;  ///< Wall time summed over all calls.
  std::uint64_t last_ns = 0;   ///< Wall time of the latest call.
};

}  // namespace silva::ecs
