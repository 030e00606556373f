#pragma once
/// @file Capture figures of `silva bench`: thesis Tables 5.5-5.9, the autopilot and capture thread
/// scaling. Every capture figure is timed warm: the world the views need is generated before the
/// clock starts (the thesis captured from a generated scene; generation is Tables 5.1-5.4), then
/// render, shade, encode and write into a scratch folder that is deleted afterwards. Figures are
/// appended to `out` as they are measured; a run stopped by Ctrl-C throws Interrupted.
#include <vector>

#include "bench/harness/bench_context.hpp"

namespace silva::bench {

/// The thesis's capture set: RGB + semantic + depth.
inline const std::vector<std::string> kThesisSet = {"rgb", "semantic", "depth"};

/// Tables 5.5 (density), 5.6 (resolution), 5.7 (number of captures), 5.8 (one output type),
/// 5.9 (type switching: Silva renders every type from one pass, so a "switch" is the marginal
/// per-set cost of adding the second type to the first).
void bench_capture(const BenchContext& ctx, std::vector<Figure>& out);

/// "threads-capture" (plan.scaling_frames autopilot frames on 1..n threads) and "autopilot" (the
/// whole autopilot, or with plan.autopilot_frames > 0 that subset scaled to the whole, marked extrapolated).
void bench_autopilot_and_scaling(const BenchContext& ctx, std::vector<Figure>& out);

}  // namespace silva::bench
