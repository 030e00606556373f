#include "ecs/sparse_set.hpp"

namespace silva::ecs {

bool SparseSet::remove(Entity e) {
  if (!contains(e)) return false;
  const std::uint32_t pos = sparse_[e.index];
  const Entity last = dense_.back();
  dense_[pos] = last;
  sparse_[last.index] = pos;
  dense_.pop_back();
  sparse_[e.index] = kAbsent;
  swap_pop_payload(pos);
  return true;
}

std::size_t SparseSet::push_entity(Entity e) {
  if (e.index >= sparse_.size()) sparse_.resize(std::size_t(e.index) + 1, kAbsent);
  sparse_[e.index] = static_cast<std::uint32_t>(dense_.size());
  dense_.push_back(e);
  return dense_.size() - 1;
}

}  // namespace silva::ecs
