#pragma once
/// @file A thread-safe pool of objects handed out and taken back, so that their buffers are allocated once per run.
#include <memory>
#include <mutex>
#include <vector>

namespace silva {

/// Objects of type T lent out as shared pointers and shelved again when their last owner drops them: as many
/// exist as were ever lent at once. Copies of a pool share one shelf (lend from it and return to it), and a lent
/// object may outlive every copy of its pool.
template <class T>
class RecyclingPool {
 public:
  /// A shelved object (a new, default-constructed one when the shelf is empty).
  std::shared_ptr<T> take() {
    std::unique_ptr<T> object;
    {
      const std::lock_guard lock(shelf_->mutex);
      if (!shelf_->free.empty()) {
        object = std::move(shelf_->free.back());
        shelf_->free.pop_back();
      }
    }
    if (!object) object = std::make_unique<T>();
    return std::shared_ptr<T>(object.release(), [shelf = shelf_](T* p) {
      const std::lock_guard lock(shelf->mutex);
      shelf->free.emplace_back(p);
    });
  }

 private:
  /// The objects not lent out.
  struct Shelf {
    std::mutex mutex;
    std::vector<std::unique_ptr<T>> free;
  };
  std::shared_ptr<Shelf> shelf_ = std::make_shared<Shelf>();
};

}  // namespace silva
