#include "ecs/access.hpp"

namespace silva::ecs {

void Access::declare(AccessKind kind, std::uint32_t type, std::string_view name, bool write) {
  for (AccessEntry& e : entries_) {
    if (e.kind == kind && e.type == type) {
      e.write = e.write || write;
      return;
    }
  }
  entries_.push_back(AccessEntry{kind, type, name, write});
}

const AccessEntry* Access::find(AccessKind kind, std::uint32_t type) const {
  for (const AccessEntry& e : entries_) {
    if (e.kind == kind && e.type == type) return &e;
  }
  return nullptr;
}

bool Access::can_read(AccessKind kind, std::uint32_t type) const { return find(kind, type) != nullptr; }

bool Access::can_write(AccessKind kind, std::uint32_t type) const {
  const AccessEntry* e = find(kind, type);
  return e != nullptr && e->write;
}

std::vector<AccessClash> clashes(const Access& a, const Access& b) {
  std::vector<AccessClash> out;
  for (const AccessEntry& ea : a.entries()) {
    for (const AccessEntry& eb : b.entries()) {
      if (ea.kind == eb.kind && ea.type == eb.type && (ea.write || eb.write)) {
        out.push_back(AccessClash{ea.kind, ea.name, ea.write, eb.write});
      }
    }
  }
  return out;
}

}  // namespace silva::ecs
