#include "ecs/command_buffer.hpp"

#include <string>

#include "ecs/error.hpp"

namespace silva::ecs {

CommandBuffer::Target CommandBuffer::checked(Target t) const {
  if (t.pending != Entity::kNullIndex && t.pending >= spawn_count_) {
    throw Error("ecs: command buffer got pending entity " + std::to_string(t.pending) +
                " that it did not spawn (" + std::to_string(spawn_count_) + " spawns recorded)");
  }
  return t;
}

ApplyResult CommandBuffer::apply(Registry& registry) {
  ApplyResult result;
  result.spawned.resize(spawn_count_);
  for (const Command& c : commands_) {
    if (c.op == Op::spawn) {
      result.spawned[c.target.pending] = registry.spawn();
      continue;
    }
    const Entity e = c.target.pending == Entity::kNullIndex ? c.target.entity : result.spawned[c.target.pending];
    if (!registry.alive(e)) {
      ++result.skipped;
      continue;
    }
    switch (c.op) {
      case Op::despawn: registry.despawn(e); break;
      case Op::component: c.fn(*this, registry, e, c.slot); break;
      case Op::call: callbacks_[c.slot](registry, e); break;
      case Op::spawn: break;
    }
  }
  clear();
  return result;
}

void CommandBuffer::clear() {
  commands_.clear();
  values_.clear();
  callbacks_.clear();
  spawn_count_ = 0;
}

}  // namespace silva::ecs
