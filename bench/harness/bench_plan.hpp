#pragma once
/// @file How much `silva bench` measures: sweep sizes of the full run, the quick run, and tests.
#include <string>
#include <vector>

namespace silva::bench {

/// Sweep sizes of one harness run. The thesis's x values (densities, resolutions, ...) are always
/// all measured; these sizes decide how many frames and repetitions each point gets.
struct BenchPlan {
  std::string kind = "full";           ///< "full" or "quick" (results of different kinds are not compared).
  std::vector<std::string> overrides;  ///< `--set` assignments applied to the built-in defaults first.
  int generation_repeats = 3;          ///< World builds per generation point (the median is reported).
  int frames_per_point = 5;            ///< Random capture sets per capture point (5.5, 5.6, 5.8, 5.9).
  int captures_max = 100;              ///< Frames of the 5.7 run (larger x are extrapolated).
  int autopilot_frames = 0;            ///< Autopilot frames captured: 0 = every planned frame.
  int scaling_frames = 30;             ///< Autopilot subset for capture thread scaling.
  std::vector<int> threads;            ///< Thread counts for the scaling runs, ascending.
};

/// Thread counts 1..n: every count up to 4, then doubling, always ending with n.
std::vector<int> scaling_threads(int n);

/// The full run (about 20 minutes on 2 cores): 690 autopilot frames, 100 random captures.
BenchPlan full_plan(int cores);

/// The quick run (about 3 minutes on 2 cores): one world per generation point, 2 frames per capture
/// point, 10 random captures, the 30-frame autopilot subset scaled to 690 (labelled extrapolated).
BenchPlan quick_plan(int cores);

}  // namespace silva::bench
