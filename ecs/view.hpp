#pragma once
/// @file Views: iteration over the entities that have every one of a set of components.
#include <algorithm>
#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include <tbb/parallel_for.h>

#include "ecs/entity.hpp"
#include "ecs/error.hpp"
#include "ecs/fwd.hpp"
#include "ecs/pool.hpp"

namespace silva::ecs {

namespace detail {
/// Calls fn(e, cs...) when it takes the entity, else fn(cs...).
template <class Fn, class... Cs>
void invoke_each(Fn& fn, Entity e, Cs&... cs) {
  if constexpr (std::is_invocable_v<Fn&, Entity, Cs&...>) {
    fn(e, cs...);
  } else {
    static_assert(std::is_invocable_v<Fn&, Cs&...>,
                  "each: the callback must take (Entity, Components&...) or (Components&...)");
    fn(cs...);
  }
}
}  // namespace detail

/// The entities having all of Ts (a `const T` is read-only). Iteration walks the dense
/// entity array of the smallest pool and looks the others up, so it costs O(smallest pool).
/// The pools must not change structurally while a view is iterated: record spawns,
/// despawns and component adds/removes in a CommandBuffer instead.
template <class... Ts>
class View {
  static_assert(sizeof...(Ts) >= 1, "a view needs at least one component type");

 public:
  /// A view over the given pools; a null pool (type never stored) makes the view empty.
  explicit View(Pool<std::remove_const_t<Ts>>*... pools) : pools_(pools...) {
    const std::array<const SparseSet*, sizeof...(Ts)> sets{pools...};
    for (const SparseSet* s : sets) {
      if (s == nullptr) {
        driver_ = nullptr;
        return;
      }
      if (driver_ == nullptr || s->size() < driver_->size()) driver_ = s;
    }
  }

  /// Entities walked by an iteration (the smallest pool's size), an upper bound on matches.
  std::size_t size_hint() const { return driver_ ? driver_->size() : 0; }
  /// True if `e` has every component of the view.
  bool contains(Entity e) const {
    return driver_ && std::apply([e](auto*... p) { return (p->contains(e) && ...); }, pools_);
  }
  /// Calls fn(Entity, Ts&...) or fn(Ts&...) for every matching entity, in dense order.
  template <class Fn>
  void each(Fn&& fn) const {
    each_in_range(0, size_hint(), fn);
  }
  /// Number of fixed-size chunks the iteration splits into (independent of thread count).
  std::size_t chunk_count(std::size_t chunk_size) const {
    check_chunk_size(chunk_size);
    return (size_hint() + chunk_size - 1) / chunk_size;
  }
  /// Iterates only chunk `chunk`: dense positions [chunk*chunk_size, (chunk+1)*chunk_size).
  template <class Fn>
  void each_in_chunk(std::size_t chunk, std::size_t chunk_size, Fn&& fn) const {
    check_chunk_size(chunk_size);
    const std::size_t begin = chunk * chunk_size;
    each_in_range(begin, std::min(size_hint(), begin + chunk_size), fn);
  }
  /// Like each(), with chunks run concurrently on TBB; `fn` must be safe to call in parallel
  /// for different entities. Which entities form a chunk never depends on the thread count.
  template <class Fn>
  void parallel_each(Fn&& fn, std::size_t chunk_size = kDefaultChunkSize) const {
    tbb::parallel_for(std::size_t{0}, chunk_count(chunk_size),
                      [&](std::size_t c) { each_in_chunk(c, chunk_size, fn); });
  }

 private:
  static void check_chunk_size(std::size_t chunk_size) {
    if (chunk_size == 0) throw Error("ecs: view chunk size must be at least 1");
  }

  template <class Fn>
  void each_in_range(std::size_t begin, std::size_t end, Fn& fn) const {
    each_in_range(begin, end, fn, std::index_sequence_for<Ts...>{});
  }

  template <class Fn, std::size_t... I>
  void each_in_range(std::size_t begin, std::size_t end, Fn& fn, std::index_sequence<I...>) const {
    if (driver_ == nullptr) return;
    const auto entities = driver_->entities();
    for (std::size_t i = begin; i < end; ++i) {
      const Entity e = entities[i];
      if (!(has<I>(e) && ...)) continue;
      detail::invoke_each(fn, e, fetch<I>(i, e)...);
    }
  }

  template <std::size_t I>
  bool has(Entity e) const {
    const auto* p = std::get<I>(pools_);
    return p == driver_ || p->contains_index(e.index);
  }

  template <std::size_t I>
  std::tuple_element_t<I, std::tuple<Ts...>>& fetch(std::size_t i, Entity e) const {
    auto* p = std::get<I>(pools_);
    return p->at(p == driver_ ? i : p->position(e));
  }

  std::tuple<Pool<std::remove_const_t<Ts>>*...> pools_;
  const SparseSet* driver_ = nullptr;
};

}  // namespace silva::ecs
