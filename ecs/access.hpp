#pragma once
/// @file Access declarations: which components and resources a system reads or writes.
#include <cstdint>
#include <string_view>
#include <vector>

#include "ecs/type_info.hpp"

namespace silva::ecs {

/// Whether an access is to a component pool or to a resource.
enum class AccessKind : std::uint8_t { component, resource };

/// One declared access; `write` implies read.
struct AccessEntry {
  AccessKind kind;        ///< Component or resource.
  std::uint32_t type;     ///< type_id of the accessed type.
  std::string_view name;  ///< type_name of the accessed type.
  bool write;             ///< True for write access.
};

/// Two systems' accesses that collide: one writes what the other reads or writes.
struct AccessClash {
  AccessKind kind;        ///< Component or resource.
  std::string_view name;  ///< Name of the shared type.
  bool first_writes;      ///< Whether the first system writes it.
  bool second_writes;     ///< Whether the second system writes it.
};

/// The set of accesses one system declared, in declaration order.
class Access {
 public:
  /// Declares read (or, with write, write) access to T; write wins over read.
  template <class T>
  void declare(AccessKind kind, bool write) {
    declare(kind, type_id<T>(), type_name<T>(), write);
  }
  /// Declares access to a type by id; write wins over read.
  void declare(AccessKind kind, std::uint32_t type, std::string_view name, bool write);
  /// True if the type may be read (declared read or write).
  bool can_read(AccessKind kind, std::uint32_t type) const;
  /// True if the type may be written.
  bool can_write(AccessKind kind, std::uint32_t type) const;
  /// Every declared access, in declaration order.
  const std::vector<AccessEntry>& entries() const { return entries_; }

 private:
  const AccessEntry* find(AccessKind kind, std::uint32_t type) const;

  std::vector<AccessEntry> entries_;
};

/// Every type where `a` and `b` collide, in `a`'s declaration order.
std::vector<AccessClash> clashes(const Access& a, const Access& b);

}  // namespace silva::ecs
