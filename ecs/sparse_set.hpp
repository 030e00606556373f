#pragma once
/// @file Sparse set of entities: the dense entity array every component pool is built on.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "ecs/entity.hpp"

namespace silva::ecs {

/// Dense array of entities plus a sparse index (entity slot -> dense position).
/// Removal swaps the last element into the hole, so the dense array stays packed; the
/// order is a pure function of the sequence of insertions and removals.
class SparseSet {
 public:
  /// Position value meaning "not in the set".
  static constexpr std::uint32_t kAbsent = 0xFFFFFFFFu;

  /// A set whose elements are described by `element_name` in messages.
  explicit SparseSet(std::string_view element_name) : name_(element_name) {}
  virtual ~SparseSet() = default;
  SparseSet(const SparseSet&) = delete;
  SparseSet& operator=(const SparseSet&) = delete;

  /// Number of entities in the set.
  std::size_t size() const { return dense_.size(); }
  /// True if the set holds exactly this handle (index and generation).
  bool contains(Entity e) const {
    return contains_index(e.index) && dense_[sparse_[e.index]] == e;
  }
  /// True if the set holds some entity in slot `index` (enough for live handles).
  bool contains_index(std::uint32_t index) const {
    return index < sparse_.size() && sparse_[index] != kAbsent;
  }
  /// Dense position of an entity known to be in the set.
  std::size_t position(Entity e) const { return sparse_[e.index]; }
  /// The dense entity array, in storage order.
  std::span<const Entity> entities() const { return dense_; }
  /// Name of what the set stores (the component type), for messages.
  std::string_view name() const { return name_; }
  /// Removes `e` if present (swap with last, pop); returns whether it was present.
  bool remove(Entity e);

 protected:
  /// Reserves room for `n` entities in the dense array.
  void reserve_entities(std::size_t n) { dense_.reserve(n); }
  /// Appends `e` (which must be absent) and returns its dense position.
  std::size_t push_entity(Entity e);

 private:
  /// Moves the payload at the last position into `position`, then drops the last payload.
  virtual void swap_pop_payload(std::size_t position) = 0;

  std::string_view name_;
  std::vector<std::uint32_t> sparse_;
  std::vector<Entity> dense_;
};

}  // namespace silva::ecs
