#include "ecs/entity_allocator.hpp"

#include "ecs/error.hpp"

namespace silva::ecs {

Entity EntityAllocator::create() {
  if (!free_.empty()) {
    const std::uint32_t index = free_.back();
    free_.pop_back();
    in_use_[index] = 1;
    return Entity{index, generations_[index]};
  }
  if (generations_.size() >= Entity::kNullIndex) throw Error("ecs: entity table is full (2^32-1 slots)");
  const auto index = static_cast<std::uint32_t>(generations_.size());
  generations_.push_back(0);
  in_use_.push_back(1);
  return Entity{index, 0};
}

bool EntityAllocator::destroy(Entity e) {
  if (!alive(e)) return false;
  in_use_[e.index] = 0;
  if (++generations_[e.index] == 0xFFFFFFFFu) {
    ++retired_;  // a further reuse would wrap the generation and let a stale handle alias
  } else {
    free_.push_back(e.index);
  }
  return true;
}

}  // namespace silva::ecs
