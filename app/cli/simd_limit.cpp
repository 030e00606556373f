#include "app/cli/simd_limit.hpp"

#include <cstdint>

#include <hwy/targets.h>

#include "core/error.hpp"
#include "raycast/ray_scene.hpp"

namespace silva::app {

namespace {
/// simd_limit's value.
std::string& limit_applied() {
  static std::string limit;
  return limit;
}
}  // namespace

void apply_simd_limit(const std::string& limit) {
  const int64_t above_avx2 = HWY_AVX3 | HWY_AVX3_DL;
  if (limit == "avx2") {
    hwy::DisableTargets(above_avx2);
    raycast::set_default_device_config("isa=avx2");
  } else if (limit == "sse4") {
    hwy::DisableTargets(above_avx2 | HWY_AVX2);
    raycast::set_default_device_config("isa=sse4.2");
  } else {
    throw InputError("SILVA_SIMD_LIMIT=" + limit + ": expected avx2 or sse4 (or leave it unset)");
  }
  limit_applied() = limit;
}

const std::string& simd_limit() { return limit_applied(); }

std::vector<std::string> simd_targets() {
  std::vector<std::string> names;
  const uint64_t usable = static_cast<uint64_t>(hwy::SupportedTargets() & HWY_TARGETS);
  for (uint64_t bit = 1; bit != 0; bit <<= 1) {
    if ((usable & bit) != 0) names.emplace_back(hwy::TargetName(static_cast<int64_t>(bit)));
  }
  return names;  // Highway numbers better targets with lower bits
}

}  // namespace silva::app
