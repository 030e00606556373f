#pragma once
/// @file Running a SIMD kernel under every Highway target this CPU can run (determinism tests).
#include <cstdint>
#include <vector>

#include "hwy/targets.h"

namespace silva::render::test {

/// The compiled Highway targets this CPU supports, best first; the last is the portable one.
inline std::vector<int64_t> highway_targets() {
  hwy::SetSupportedTargetsForTest(0);
  return hwy::SupportedAndGeneratedTargets();
}

/// Pins Highway's dynamic dispatch to one target while it lives, then restores normal dispatch.
struct PinnedTarget {
  /// Dispatches every HWY_DYNAMIC_DISPATCH call to `target` from now on.
  explicit PinnedTarget(int64_t target) { hwy::SetSupportedTargetsForTest(target); }
  ~PinnedTarget() { hwy::SetSupportedTargetsForTest(0); }
  PinnedTarget(const PinnedTarget&) = delete;             ///< Not copyable.
  PinnedTarget& operator=(const PinnedTarget&) = delete;  ///< Not assignable.
};

}  // namespace silva::render::test
