#include "bench/harness/bench_plan.hpp"

#include <algorithm>

namespace silva::bench {

std::vector<int> scaling_threads(int n) {
  n = std::max(1, n);
  std::vector<int> out;
  for (int t = 1; t <= n; t = t < 4 ? t + 1 : t * 2) out.push_back(t);
  if (out.back() != n) out.push_back(n);
  return out;
}

BenchPlan full_plan(int cores) {
  BenchPlan p;
  p.threads = scaling_threads(cores);
  return p;
}

BenchPlan quick_plan(int cores) {
  BenchPlan p;
  p.kind = "quick";
  p.generation_repeats = 1;
  p.frames_per_point = 2;
  p.captures_max = 10;
  p.autopilot_frames = 30;
  p.threads = scaling_threads(cores);
  return p;
}

}  // namespace silva::bench
