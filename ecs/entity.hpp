#pragma once
/// @file Entity handles: a 32-bit slot index plus a 32-bit generation.
#include <compare>
#include <cstdint>
#include <functional>
#include <string>

namespace silva::ecs {

/// A handle to an entity; a handle whose slot was reused has an older generation (stale).
struct Entity {
  /// Index value of the null handle.
  static constexpr std::uint32_t kNullIndex = 0xFFFFFFFFu;

  std::uint32_t index = kNullIndex;  ///< Slot in the entity table.
  std::uint32_t generation = 0;      ///< Times the slot was freed before this handle was made.

  /// True for handles that never referred to an entity.
  constexpr bool is_null() const { return index == kNullIndex; }
  /// Index and generation packed into one word (generation high).
  constexpr std::uint64_t bits() const { return (std::uint64_t(generation) << 32) | index; }

  /// Handles are equal when index and generation both match.
  friend constexpr bool operator==(Entity, Entity) = default;
  /// Orders by index, then generation.
  friend constexpr auto operator<=>(Entity, Entity) = default;
};

/// The handle that refers to no entity.
inline constexpr Entity null_entity{};

/// "#index.vgeneration", or "null", for messages.
inline std::string to_string(Entity e) {
  if (e.is_null()) return "null";
  std::string s = "#";
  s += std::to_string(e.index);
  s += ".v";
  s += std::to_string(e.generation);
  return s;
}

}  // namespace silva::ecs

/// Hash of an entity handle, so handles can key unordered containers.
template <>
struct std::hash<silva::ecs::Entity> {
  /// Hashes the packed index and generation.
  std::size_t operator()(silva::ecs::Entity e) const noexcept { return std::hash<std::uint64_t>{}(e.bits()); }
};
