#pragma once
/// @file Registry: entities and their components, stored in one pool per component type.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "ecs/entity.hpp"
#include "ecs/entity_allocator.hpp"
#include "ecs/error.hpp"
#include "ecs/pool.hpp"
#include "ecs/type_info.hpp"
#include "ecs/view.hpp"

namespace silva::ecs {

/// Owns entities and component pools. Structural changes (spawn, despawn, add, remove)
/// are single-threaded; concurrent readers/writers of component values are fine while no
/// structural change happens (systems defer theirs through command buffers).
class Registry {
 public:
  Registry() = default;
  Registry(const Registry&) = delete;
  Registry& operator=(const Registry&) = delete;
  Registry(Registry&&) = default;
  Registry& operator=(Registry&&) = default;

  /// Makes a live entity holding the given components.
  template <class... Ts>
  Entity spawn(Ts&&... components) {
    const Entity e = entities_.create();
    (add(e, std::forward<Ts>(components)), ...);
    return e;
  }
  /// Removes a live entity and all its components; false (no effect) for a stale handle.
  bool despawn(Entity e);
  /// True if `e` refers to a live entity.
  bool alive(Entity e) const { return entities_.alive(e); }
  /// Number of live entities.
  std::size_t entity_count() const { return entities_.live_count(); }

  /// Gives `e` the component `value` (replacing any it had); throws Error if `e` is stale.
  template <class T>
  std::decay_t<T>& add(Entity e, T&& value) {
    using C = std::decay_t<T>;
    if (!alive(e)) throw Error("ecs: add<" + std::string(type_name<C>()) + "> on stale entity " + to_string(e));
    return pool<C>().put(e, std::forward<T>(value));
  }
  /// Takes component T away from `e`; false if `e` is stale or had no T.
  template <class T>
  bool remove(Entity e) {
    Pool<T>* p = find_pool<T>();
    return p != nullptr && alive(e) && p->remove(e);
  }
  /// True if `e` is live and has a T.
  template <class T>
  bool has(Entity e) const {
    const Pool<std::remove_const_t<T>>* p = find_pool<std::remove_const_t<T>>();
    return p != nullptr && alive(e) && p->contains(e);
  }
  /// The T of `e`; throws Error naming the handle if `e` is stale or has no T.
  template <class T>
  T& get(Entity e) {
    Pool<std::remove_const_t<T>>* p = find_pool<std::remove_const_t<T>>();
    check_has<T>(p, e);
    return p->get(e);
  }
  /// The T of `e`; throws Error naming the handle if `e` is stale or has no T.
  template <class T>
  const T& get(Entity e) const {
    const Pool<std::remove_const_t<T>>* p = find_pool<std::remove_const_t<T>>();
    check_has<T>(p, e);
    return p->get(e);
  }
  /// The T of `e`, or nullptr if `e` is stale or has no T.
  template <class T>
  T* try_get(Entity e) {
    Pool<std::remove_const_t<T>>* p = find_pool<std::remove_const_t<T>>();
    return p != nullptr && alive(e) && p->contains(e) ? &p->get(e) : nullptr;
  }
  /// The entities having all of Ts (`const T` for read-only access).
  template <class... Ts>
  View<Ts...> view() {
    return View<Ts...>(find_pool<std::remove_const_t<Ts>>()...);
  }
  /// The pool of T, made empty on first use (a structural change).
  template <class T>
  Pool<T>& pool() {
    const std::uint32_t id = type_id<T>();
    if (id >= pools_.size()) pools_.resize(std::size_t(id) + 1);
    if (!pools_[id]) pools_[id] = std::make_unique<Pool<T>>();
    return static_cast<Pool<T>&>(*pools_[id]);
  }
  /// The pool of T, or nullptr if no T was ever stored.
  template <class T>
  Pool<T>* find_pool() {
    const std::uint32_t id = type_id<T>();
    return id < pools_.size() ? static_cast<Pool<T>*>(pools_[id].get()) : nullptr;
  }
  /// The pool of T, or nullptr if no T was ever stored.
  template <class T>
  const Pool<T>* find_pool() const {
    const std::uint32_t id = type_id<T>();
    return id < pools_.size() ? static_cast<const Pool<T>*>(pools_[id].get()) : nullptr;
  }

 private:
  template <class T, class P>
  void check_has(P* p, Entity e) const {
    if (!alive(e)) {
      throw Error("ecs: get<" + std::string(type_name<T>()) + "> on stale entity " + to_string(e) +
                  " (it was despawned)");
    }
    if (p == nullptr || !p->contains(e)) {
      throw Error("ecs: get<" + std::string(type_name<T>()) + ">: entity " + to_string(e) + " has no " +
                  std::string(type_name<T>()));
    }
  }

  EntityAllocator entities_;
  std::vector<std::unique_ptr<SparseSet>> pools_;  // indexed by type_id
};

}  // namespace silva::ecs
