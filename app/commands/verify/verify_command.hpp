#pragma once
/// @file What `silva verify` asks of the pipeline, its exit code for a failed check, and its run function.
#include <filesystem>

#include "pipeline/console/reporter.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

/// `silva verify DIR`: re-cast frames of a finished dataset with the ray caster and compare.
struct VerifyRequest {
  std::filesystem::path run_dir;    ///< <output.dir>/<seed>/.
  int frames = 8;                   ///< --frames N: frames checked (all when the dataset has fewer).
  double sample = 0.25;             ///< --sample F: share of each frame's pixels cast, in (0, 1].
  double min_class = 99.9;          ///< --min-class: % of interior pixels whose class must agree.
  double min_depth = 99.9;          ///< --min-depth: % of hit pixels whose depth must agree.
  double depth_tolerance = 0.1;     ///< --depth-tolerance: relative depth error (%) that still agrees.
  bool full_detail = false;         ///< --full-detail: cast full detail even where the dataset drew a coarser LOD.
};

/// Exit code of `silva verify` when the dataset does not meet the thresholds (CONTRACT.md).
inline constexpr int kExitVerifyFailed = 4;

/// Verifies a finished dataset, writes DIR/verify.json and DIR/VERIFY.md; returns 0 when it meets the
/// thresholds, kExitVerifyFailed when not. Throws InputError / IoError.
int run_verify(const VerifyRequest& request, const Reporter& reporter);

}  // namespace silva::app
