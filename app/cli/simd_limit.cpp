#include "app/cli/simd_limit.hpp"

#include <hwy/targets.h>

#include "core/error.hpp"
#include "raycast/ray_scene.hpp"

namespace silva::app {

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
}

}  // namespace silva::app
