#include "core/trail_surface.hpp"

namespace silva {

std::string_view trail_surface_name(TrailSurface s) { return kTrailSurfaceNames[size_t(s)]; }

bool parse_trail_surface(std::string_view name, TrailSurface& out) {
  for (size_t i = 0; i < kTrailSurfaceNames.size(); ++i)
    if (kTrailSurfaceNames[i] == name) {
      out = TrailSurface(i);
      return true;
    }
  return false;
}

}  // namespace silva
