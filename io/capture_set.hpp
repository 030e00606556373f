#pragma once
/// @file Encodes every selected output of one capture (frame) in parallel into in-memory files.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/ontology.hpp"
#include "io/output_types.hpp"
#include "io/label_planes.hpp"

namespace silva::io {

/// One encoded file of a capture set.
struct EncodedFile {
  std::string relative_path;   ///< Path inside the sequence folder, e.g. "depth/000042.png".
  std::vector<uint8_t> bytes;  ///< The whole file.
};

/// All files of one capture set, in OutputType order (instance: PNG, then JSON).
using EncodedSet = std::vector<EncodedFile>;

/// "<folder>/<frame as %06d>.<ext>", e.g. frame_file("camera", 7, "json") = "camera/000007.json".
std::string frame_file(const std::string& folder, int frame, const std::string& ext);

/// The folder of output `name` for one camera of the rig: `name` for the mono or left camera, "<name>_right" for a
/// stereo pair's right camera.
std::string camera_folder(const std::string& name, bool right);

/// The image files encode_capture_set writes for frame `frame` of `selection`, in the same order
/// (relative to the sequence folder; the camera file is not among them); with `stereo`, then the right
/// camera's, its camera file and the left camera's disparity.
std::vector<std::string> frame_file_names(const OutputSelection& selection, int frame, bool stereo);

/// Encodes the selected outputs of frame `frame` (of the right camera's folders when `right`) from its G-buffer and RGB image (interleaved
/// R, G, B, width*height*3 bytes; may be empty when rgb is not selected) on the caller's TBB
/// arena, one task per output. The result does not depend on the thread count.
/// Throws InputError when the instance image would overflow (see instance_image).
EncodedSet encode_capture_set(const LabelPlanes& gbuffer, std::span<const uint8_t> rgb, const Ontology& ontology,
                              const OutputSelection& selection, int frame, bool right);

}  // namespace silva::io
