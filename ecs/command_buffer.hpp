#pragma once
/// @file Deferred structural changes: spawn, despawn, add and remove recorded now, applied later.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include "ecs/entity.hpp"
#include "ecs/registry.hpp"
#include "ecs/type_info.hpp"

namespace silva::ecs {

/// An entity a CommandBuffer will spawn; meaningful only in the buffer that made it.
struct PendingEntity {
  std::uint32_t slot = 0;  ///< Index among this buffer's spawns, and into ApplyResult::spawned.
};

/// What applying a buffer did.
struct ApplyResult {
  std::vector<Entity> spawned;  ///< Real handle of each PendingEntity, by slot.
  std::size_t skipped = 0;      ///< Commands dropped because their entity was no longer alive.
};

/// Records structural changes without touching the registry; apply() replays them in
/// recording order. Handles of spawned entities are assigned at apply time, in apply
/// order, so they depend only on the order in which buffers are applied — never on which
/// thread recorded what. Commands aimed at entities that died before apply are skipped.
/// One buffer is used by one thread at a time.
class CommandBuffer {
 public:
  /// A target: an existing entity or one this buffer spawns.
  struct Target {
    Entity entity;                                   ///< Existing entity (when not pending).
    std::uint32_t pending = Entity::kNullIndex;      ///< Spawn slot, or kNullIndex.
    /// Targets an existing entity.
    Target(Entity e) : entity(e) {}  // NOLINT(google-explicit-constructor): implicit by design
    /// Targets an entity this buffer spawns.
    Target(PendingEntity p) : pending(p.slot) {}  // NOLINT(google-explicit-constructor)
  };

  /// Records the spawn of an entity holding `components`.
  template <class... Ts>
  PendingEntity spawn(Ts&&... components) {
    const PendingEntity p{spawn_count_++};
    commands_.push_back(Command{Op::spawn, Target(p), 0, nullptr});
    (add(p, std::forward<Ts>(components)), ...);
    return p;
  }
  /// Records the despawn of `target`.
  void despawn(Target target) { commands_.push_back(Command{Op::despawn, checked(target), 0, nullptr}); }
  /// Records giving `target` the component `value` (replacing any it has then).
  template <class T>
  void add(Target target, T&& value) {
    using C = std::decay_t<T>;
    auto& list = values<C>();
    const auto slot = static_cast<std::uint32_t>(list.size());
    list.push_back(std::forward<T>(value));
    commands_.push_back(Command{Op::component, checked(target), slot, &apply_add<C>});
  }
  /// Records taking component T away from `target`.
  template <class T>
  void remove(Target target) {
    commands_.push_back(Command{Op::component, checked(target), 0, &apply_remove<T>});
  }
  /// Records a call fn(registry, entity) once `target` exists (e.g. to learn a spawned handle).
  void then(Target target, std::function<void(Registry&, Entity)> fn) {
    const auto slot = static_cast<std::uint32_t>(callbacks_.size());
    callbacks_.push_back(std::move(fn));
    commands_.push_back(Command{Op::call, checked(target), slot, nullptr});
  }
  /// Number of recorded commands.
  std::size_t size() const { return commands_.size(); }
  /// True if nothing is recorded.
  bool empty() const { return commands_.empty(); }
  /// Replays every command in recording order, then clears the buffer.
  ApplyResult apply(Registry& registry);

 private:
  enum class Op : std::uint8_t { spawn, despawn, component, call };
  using ApplyFn = void (*)(CommandBuffer&, Registry&, Entity, std::uint32_t);
  struct Command {
    Op op;
    Target target;
    std::uint32_t slot;  // value or callback index
    ApplyFn fn;          // for Op::component
  };
  struct ValueListBase {
    virtual ~ValueListBase() = default;
  };
  template <class T>
  struct ValueList final : ValueListBase {
    std::vector<T> items;
  };

  template <class T>
  std::vector<T>& values() {
    const std::uint32_t id = type_id<T>();
    if (id >= values_.size()) values_.resize(std::size_t(id) + 1);
    if (!values_[id]) values_[id] = std::make_unique<ValueList<T>>();
    return static_cast<ValueList<T>&>(*values_[id]).items;
  }
  template <class T>
  static void apply_add(CommandBuffer& self, Registry& r, Entity e, std::uint32_t slot) {
    r.add(e, std::move(self.values<T>()[slot]));
  }
  template <class T>
  static void apply_remove(CommandBuffer&, Registry& r, Entity e, std::uint32_t) {
    r.remove<T>(e);
  }
  Target checked(Target t) const;
  void clear();

  std::vector<Command> commands_;
  std::vector<std::unique_ptr<ValueListBase>> values_;  // indexed by type_id
  std::vector<std::function<void(Registry&, Entity)>> callbacks_;
  std::uint32_t spawn_count_ = 0;
};

}  // namespace silva::ecs
