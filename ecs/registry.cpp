#include "ecs/registry.hpp"

namespace silva::ecs {

bool Registry::despawn(Entity e) {
  if (!alive(e)) return false;
  for (const auto& p : pools_) {
    if (p) p->remove(e);
  }
  return entities_.destroy(e);
}

}  // namespace silva::ecs
