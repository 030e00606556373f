#pragma once
/// @file SILVA_SIMD_LIMIT: runs Silva as on a CPU with fewer vector instructions, to check that its
/// files do not depend on the machine (they must not) and to measure what such a CPU costs.
#include <string>

namespace silva::app {

/// Caps the SIMD code this process runs at `limit`: "avx2" (Highway's AVX2 target at most, Embree's
/// AVX2 kernels) or "sse4" (Highway's SSE4, Embree's SSE4.2 kernels). Call before any work. Throws
/// InputError naming SILVA_SIMD_LIMIT and the allowed values for anything else.
void apply_simd_limit(const std::string& limit);

}  // namespace silva::app
