#pragma once
/// @file Component pool: a sparse set of entities with a parallel dense array of components.
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "ecs/sparse_set.hpp"
#include "ecs/type_info.hpp"

namespace silva::ecs {

/// Structure-of-arrays storage for one component type: entities()[i] owns components()[i].
template <class T>
class Pool final : public SparseSet {
 public:
  /// An empty pool named after T.
  Pool() : SparseSet(type_name<T>()) {}

  /// Stores `value` for `e`, replacing any value it already had; returns the stored value.
  T& put(Entity e, T value) {
    if (contains(e)) return values_[position(e)] = std::move(value);
    push_entity(e);
    return values_.emplace_back(std::move(value));
  }
  /// The component of an entity known to be in the pool.
  T& get(Entity e) { return values_[position(e)]; }
  /// The component of an entity known to be in the pool.
  const T& get(Entity e) const { return values_[position(e)]; }
  /// The component at a dense position.
  T& at(std::size_t position) { return values_[position]; }
  /// The dense component array, aligned with entities().
  std::span<T> components() { return values_; }
  /// The dense component array, aligned with entities().
  std::span<const T> components() const { return values_; }
  /// Reserves room for `n` components.
  void reserve(std::size_t n) {
    reserve_entities(n);
    values_.reserve(n);
  }

 private:
  void swap_pop_payload(std::size_t position) override {
    if (position + 1 != values_.size()) values_[position] = std::move(values_.back());
    values_.pop_back();
  }

  std::vector<T> values_;
};

}  // namespace silva::ecs
