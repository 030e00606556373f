// Placeholders for pipeline entry points that are not built yet; the lead engineer replaces each
// with its implementation. They fail as internal errors (exit 1), never as bad input.
#include <stdexcept>

#include "app/commands.hpp"

namespace silva::app {

namespace {

[[noreturn]] void not_implemented(const char* command) {
  throw std::logic_error(std::string("not implemented yet: ") + command);
}

}  // namespace

int run_bench(const BenchRequest&, const Reporter&) { not_implemented("bench"); }
int run_profile_placement(const ProfilePlacementRequest&, const Reporter&) {
  not_implemented("profile placement");
}

}  // namespace silva::app
