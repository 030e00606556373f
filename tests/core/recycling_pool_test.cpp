// RecyclingPool: objects come back to the shelf their pool (or a copy of it) lent them from, and only as many
// exist as were lent at once.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "core/recycling_pool.hpp"

namespace silva {
namespace {

TEST(RecyclingPool, ReturnedObjectIsLentAgainWithItsContents) {
  RecyclingPool<std::vector<int>> pool;
  std::vector<int>* first = nullptr;
  {
    const std::shared_ptr<std::vector<int>> lent = pool.take();
    lent->assign(1000, 7);
    first = lent.get();
  }
  const std::shared_ptr<std::vector<int>> again = pool.take();
  EXPECT_EQ(again.get(), first);
  EXPECT_EQ(again->size(), 1000u);  // the buffer is kept, not freed
}

TEST(RecyclingPool, ObjectsLentAtOnceAreDistinctAndCopiesShareTheShelf) {
  RecyclingPool<int> pool;
  const RecyclingPool<int> copy = pool;
  int* a = nullptr;
  int* b = nullptr;
  {
    const std::shared_ptr<int> x = pool.take(), y = pool.take();
    EXPECT_NE(x.get(), y.get());
    a = x.get();
    b = y.get();
  }
  RecyclingPool<int> other_copy = copy;
  const std::shared_ptr<int> p = other_copy.take(), q = pool.take();
  EXPECT_TRUE((p.get() == a && q.get() == b) || (p.get() == b && q.get() == a));
  const std::shared_ptr<int> third = pool.take();  // both shelved ones are out: a new one
  EXPECT_NE(third.get(), a);
  EXPECT_NE(third.get(), b);
}

TEST(RecyclingPool, LentObjectOutlivesThePool) {
  std::shared_ptr<int> lent;
  {
    RecyclingPool<int> pool;
    lent = pool.take();
    *lent = 5;
  }
  EXPECT_EQ(*lent, 5);
  lent.reset();  // returns to a shelf no pool names any more, which it then frees (ASan checks)
}

}  // namespace
}  // namespace silva
