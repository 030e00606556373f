#pragma once
/// @file Hands out entity slots and detects stale handles through generations.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "ecs/entity.hpp"

namespace silva::ecs {

/// Entity slot table: freed slots are reused last-freed-first with a bumped generation,
/// so the sequence of handles is a pure function of the sequence of create/destroy calls.
class EntityAllocator {
 public:
  /// Makes a new live entity.
  Entity create();
  /// Frees a live entity; returns false (and does nothing) for a stale or null handle.
  bool destroy(Entity e);
  /// True if `e` refers to a live entity (its slot is in use with the same generation).
  bool alive(Entity e) const {
    return e.index < generations_.size() && in_use_[e.index] && generations_[e.index] == e.generation;
  }
  /// Number of live entities.
  std::size_t live_count() const { return generations_.size() - free_.size() - retired_; }
  /// Number of slots ever made (live, free or retired).
  std::size_t slot_count() const { return generations_.size(); }

 private:
  std::vector<std::uint32_t> generations_;
  std::vector<std::uint8_t> in_use_;
  std::vector<std::uint32_t> free_;
  std::size_t retired_ = 0;  // slots whose generation is exhausted; never reused
};

}  // namespace silva::ecs
