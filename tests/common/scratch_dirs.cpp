#include "scratch_dirs.hpp"

#include <gtest/gtest.h>

#include <iostream>
#include <mutex>
#include <vector>

namespace silva::test {

namespace {

/// The folders handed to remove_when_passed in this test program.
struct ScratchList {
  std::mutex lock;                          ///< Guards dirs.
  std::vector<std::filesystem::path> dirs;  ///< In registration order.
};

ScratchList& scratch_list() {
  static ScratchList list;
  return list;
}

/// After the last test: removes the registered folders when every test passed.
class ScratchCleanup : public ::testing::Environment {
 public:
  void TearDown() override {
    ScratchList& list = scratch_list();
    const std::lock_guard<std::mutex> hold(list.lock);
    const bool passed = ::testing::UnitTest::GetInstance()->Passed();
    for (const std::filesystem::path& dir : list.dirs) {
      if (!passed) {
        std::cerr << "kept test scratch folder " << dir.string() << "\n";
        continue;
      }
      std::error_code ignored;
      std::filesystem::remove_all(dir, ignored);
    }
    list.dirs.clear();
  }
};

[[maybe_unused]] ::testing::Environment* const registered = ::testing::AddGlobalTestEnvironment(new ScratchCleanup);

}  // namespace

void remove_when_passed(const std::filesystem::path& dir) {
  ScratchList& list = scratch_list();
  const std::lock_guard<std::mutex> hold(list.lock);
  list.dirs.push_back(dir);
}

}  // namespace silva::test
