#pragma once
/// @file The SIMD code a process runs: Highway's targets, and SILVA_SIMD_LIMIT, which runs Silva as on a
/// CPU with fewer vector instructions, to check that its files do not depend on the machine (they must
/// not) and to measure what such a CPU costs.
#include <string>
#include <vector>

namespace silva::app {

/// Caps the SIMD code this process runs at `limit`: "avx2" (Highway's AVX2 target at most, Embree's
/// AVX2 kernels) or "sse4" (Highway's SSE4, Embree's SSE4.2 kernels). Call before any work. Throws
/// InputError naming SILVA_SIMD_LIMIT and the allowed values for anything else.
void apply_simd_limit(const std::string& limit);

/// The limit apply_simd_limit set ("" when none).
const std::string& simd_limit();

/// Highway targets this build can dispatch to on this CPU under the limit, best first.
std::vector<std::string> simd_targets();

}  // namespace silva::app
