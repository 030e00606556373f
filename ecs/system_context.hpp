#pragma once
/// @file What a running system sees: checked views, resources and its command buffers.
#include <cstddef>
#include <deque>
#include <string>
#include <type_traits>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "ecs/command_buffer.hpp"
#include "ecs/error.hpp"
#include "ecs/registry.hpp"
#include "ecs/resources.hpp"
#include "ecs/system.hpp"
#include "ecs/view.hpp"

namespace silva::ecs {

/// A system's window on the world for one call. Every component or resource access is
/// checked against the system's declaration (`const T` needs a read or write declaration,
/// `T` a write declaration) and throws Error if undeclared. Structural changes go to
/// command buffers, applied at the end of the phase in a fixed order: this system's
/// commands() buffer first, then one buffer per chunk of each parallel_each, in call and
/// chunk order.
class SystemContext {
 public:
  /// Context for one call of `system`; `buffers` receives its command buffers.
  SystemContext(Registry& registry, Resources& resources, const System& system, std::deque<CommandBuffer>& buffers)
      : registry_(registry), resources_(resources), system_(system), buffers_(buffers) {
    if (buffers_.empty()) buffers_.emplace_back();
  }

  /// Name of the running system.
  const std::string& name() const { return system_.name; }
  /// The entities having all of Ts.
  template <class... Ts>
  View<Ts...> view() {
    (check_component<Ts>(), ...);
    return registry_.view<Ts...>();
  }
  /// True if `e` is alive.
  bool alive(Entity e) const { return registry_.alive(e); }
  /// True if `e` is alive and has a T (needs T declared).
  template <class T>
  bool has(Entity e) {
    check_component<const T>();
    return registry_.has<T>(e);
  }
  /// The T of `e` (`const T` to read); throws Error if stale, missing or undeclared.
  template <class T>
  T& get(Entity e) {
    check_component<T>();
    return registry_.get<T>(e);
  }
  /// The T of `e`, or nullptr if stale or missing; throws Error if undeclared.
  template <class T>
  T* try_get(Entity e) {
    check_component<T>();
    return registry_.try_get<T>(e);
  }
  /// The T resource (`const T` to read); throws Error if unset or undeclared.
  template <class T>
  T& resource() {
    constexpr bool write = !std::is_const_v<T>;
    check(AccessKind::resource, type_id<T>(), type_name<T>(), write);
    return resources_.get<T>();
  }
  /// This system's own command buffer (for use from the system's calling thread only).
  CommandBuffer& commands() { return buffers_.front(); }

  /// Calls fn for each entity having all of Ts, sequentially. `fn` takes
  /// (CommandBuffer&, Entity, Ts&...), (Entity, Ts&...) or (Ts&...); the buffer is commands().
  template <class... Ts, class Fn>
  void each(Fn&& fn) {
    const View<Ts...> v = view<Ts...>();
    if constexpr (std::is_invocable_v<Fn&, CommandBuffer&, Entity, Ts&...>) {
      CommandBuffer& cb = commands();
      v.each([&](Entity e, Ts&... c) { fn(cb, e, c...); });
    } else {
      v.each(fn);
    }
  }
  /// Like each(), over fixed-size chunks run in parallel; with the CommandBuffer& form each
  /// chunk records into its own buffer, applied in chunk order whatever the thread count.
  template <class... Ts, class Fn>
  void parallel_each(Fn&& fn, std::size_t chunk_size = kDefaultChunkSize) {
    const View<Ts...> v = view<Ts...>();
    const std::size_t chunks = v.chunk_count(chunk_size);
    if constexpr (std::is_invocable_v<Fn&, CommandBuffer&, Entity, Ts&...>) {
      const std::size_t first = buffers_.size();
      buffers_.resize(first + chunks);  // appending to a deque keeps earlier references valid
      tbb::this_task_arena::isolate([&] {
        tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
          CommandBuffer& cb = buffers_[first + c];
          v.each_in_chunk(c, chunk_size, [&](Entity e, Ts&... x) { fn(cb, e, x...); });
        });
      });
    } else {
      tbb::this_task_arena::isolate([&] { v.parallel_each(fn, chunk_size); });
    }
  }

 private:
  template <class T>
  void check_component() const {
    check(AccessKind::component, type_id<T>(), type_name<T>(), !std::is_const_v<T>);
  }
  void check(AccessKind kind, std::uint32_t type, std::string_view type_name, bool write) const {
    const bool ok = write ? system_.access.can_write(kind, type) : system_.access.can_read(kind, type);
    if (ok) return;
    const char* what = kind == AccessKind::component ? "component " : "resource ";
    const char* decl = kind == AccessKind::component ? (write ? "writes" : "reads") : (write ? "writes_resource" : "reads_resource");
    throw Error("ecs: system '" + system_.name + "' " + (write ? "writes " : "reads ") + what +
                std::string(type_name) + " without declaring it; add ." + decl + "<" + std::string(type_name) + ">()");
  }

  Registry& registry_;
  Resources& resources_;
  const System& system_;
  std::deque<CommandBuffer>& buffers_;
};

}  // namespace silva::ecs
