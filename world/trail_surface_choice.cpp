#include "world/trail_surface_choice.hpp"

#include "core/error.hpp"
#include "core/rng.hpp"

namespace silva::world {

TrailSurface trail_surface_of(const std::string& name, uint64_t seed) {
  if (name == "random") {
    Rng rng(seed, 0, Purpose::TrailSurface);
    return TrailSurface(rng.below(uint32_t(kTrailSurfaceCount)));
  }
  TrailSurface s{};
  if (parse_trail_surface(name, s)) return s;
  std::string allowed;
  for (const std::string_view n : kTrailSurfaceNames) allowed += std::string(n) + ", ";
  throw InputError("trail.surface = \"" + name + "\" is not a trail surface (allowed: " + allowed + "random)");
}

}  // namespace silva::world
