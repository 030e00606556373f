#pragma once
/// @file The optical flow files of a finished sequence (CONTRACT.md "Optical flow"): for each frame, the exact
/// flow to the next frame and to the previous one, from the dataset's depth and camera files.
#include <filesystem>
#include <string>

#include "io/dataset_reader.hpp"

namespace silva::io {

/// The folders one flow direction writes per frame: KITTI PNG, Middlebury .flo and the FlowState mask.
struct FlowFolders {
  const char* kitti;  ///< e.g. "flow_forward" (NNNNNN.png).
  const char* flo;    ///< e.g. "flow_forward_flo" (NNNNNN.flo).
  const char* mask;   ///< e.g. "flow_forward_mask" (NNNNNN.png).
};
/// Frame i to frame i + 1 (every frame but the last).
inline constexpr FlowFolders kForwardFlow = {"flow_forward", "flow_forward_flo", "flow_forward_mask"};
/// Frame i to frame i - 1 (every frame but the first).
inline constexpr FlowFolders kBackwardFlow = {"flow_backward", "flow_backward_flo", "flow_backward_mask"};

/// Writes the forward and backward flow of every frame of `sequence` into <sequence>/<folder>/ (io/optical_flow.hpp),
/// frames in parallel, each file atomically. The dataset needs depth or depth_exr (InputError naming it otherwise);
/// returns the files written.
int write_sequence_flow(const Dataset& d, const std::string& sequence);

/// write_sequence_flow of the finished run in `run_dir` for its trajectory sequence when the run's config has
/// trajectory.flow = true and the run has trajectory frames; returns the files written (0 when not).
int write_trajectory_flow(const std::filesystem::path& run_dir);

}  // namespace silva::io
