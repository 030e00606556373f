#pragma once
/// @file Resources: world-global singletons (config, asset library, counters) keyed by type.
#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "ecs/error.hpp"
#include "ecs/type_info.hpp"

namespace silva::ecs {

/// At most one value per type. Setting is a structural change (not during a frame);
/// systems read or write existing values according to their declared access.
class Resources {
 public:
  /// Stores `value` as the T resource, replacing any previous one; returns it.
  template <class T>
  std::decay_t<T>& set(T&& value) {
    using R = std::decay_t<T>;
    const std::uint32_t id = type_id<R>();
    if (id >= holders_.size()) holders_.resize(std::size_t(id) + 1);
    auto holder = std::make_unique<Holder<R>>(std::in_place, std::forward<T>(value));
    R& ref = holder->value;
    holders_[id] = std::move(holder);
    return ref;
  }
  /// The T resource, or nullptr if none was set.
  template <class T>
  T* find() const {
    using R = std::remove_const_t<T>;
    const std::uint32_t id = type_id<R>();
    if (id >= holders_.size() || !holders_[id]) return nullptr;
    return &static_cast<Holder<R>&>(*holders_[id]).value;
  }
  /// The T resource; throws Error if none was set.
  template <class T>
  T& get() const {
    T* r = find<T>();
    if (r == nullptr) throw Error("ecs: resource " + std::string(type_name<T>()) + " was never set");
    return *r;
  }
  /// Drops the T resource; false if there was none.
  template <class T>
  bool erase() {
    const std::uint32_t id = type_id<T>();
    if (id >= holders_.size() || !holders_[id]) return false;
    holders_[id].reset();
    return true;
  }

 private:
  struct HolderBase {
    virtual ~HolderBase() = default;
  };
  template <class R>
  struct Holder final : HolderBase {
    template <class U>
    Holder(std::in_place_t, U&& v) : value(std::forward<U>(v)) {}  // tagged: never a copy/move ctor
    R value;
  };

  std::vector<std::unique_ptr<HolderBase>> holders_;  // indexed by type_id
};

}  // namespace silva::ecs
