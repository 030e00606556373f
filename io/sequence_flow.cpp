#include "io/sequence_flow.hpp"

#include <algorithm>
#include <filesystem>
#include <vector>

#include <tbb/parallel_for.h>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/camera_json.hpp"
#include "io/capture_set.hpp"
#include "io/optical_flow.hpp"

namespace silva::io {

namespace fs = std::filesystem;

namespace {

/// Writes `flow` of frame `from` into `folders` of its sequence.
void write_flow(const Dataset& d, const DatasetFrame& from, const FlowField& flow, const FlowFolders& folders) {
  const fs::path seq = d.dir / from.sequence;
  write_file_atomic(seq / frame_file(folders.kitti, from.frame, "png"), encode_kitti_flow_png(flow));
  write_file_atomic(seq / frame_file(folders.flo, from.frame, "flo"), encode_middlebury_flo(flow));
  write_file_atomic(seq / frame_file(folders.mask, from.frame, "png"), encode_flow_mask_png(flow));
}

/// Writes the forward flow of frame `a` and the backward flow of the next frame `b`: one pair of depth reads.
void write_pair(const Dataset& d, const DatasetFrame& a, const DatasetFrame& b) {
  const Camera camera_a = read_camera_json(d.file(a, "camera", "json")).camera;
  const Camera camera_b = read_camera_json(d.file(b, "camera", "json")).camera;
  const cv::Mat depth_a = d.depth_metres(a, false), depth_b = d.depth_metres(b, false);
  write_flow(d, a, optical_flow(camera_a, depth_a, camera_b, depth_b), kForwardFlow);
  write_flow(d, b, optical_flow(camera_b, depth_b, camera_a, depth_a), kBackwardFlow);
}

}  // namespace

int write_sequence_flow(const Dataset& d, const std::string& sequence) {
  if (!d.has("depth") && !d.has("depth_exr"))
    throw InputError(d.dir.string() + ": optical flow needs output type 'depth' or 'depth_exr', which this dataset's "
                     "output.types does not hold");
  std::vector<DatasetFrame> frames;
  for (const DatasetFrame& f : d.frames)
    if (f.sequence == sequence) frames.push_back(f);
  for (const FlowFolders& folders : {kForwardFlow, kBackwardFlow})
    for (const char* folder : {folders.kitti, folders.flo, folders.mask}) {
      std::error_code ec;
      fs::create_directories(d.dir / sequence / folder, ec);
      if (ec) throw IoError("cannot create folder " + (d.dir / sequence / folder).string() + ": " + ec.message());
    }
  if (frames.size() < 2) return 0;
  tbb::parallel_for(size_t(0), frames.size() - 1, [&](size_t i) { write_pair(d, frames[i], frames[i + 1]); });
  return int(6 * (frames.size() - 1));
}

int write_trajectory_flow(const fs::path& run_dir) {
  const Dataset d = open_dataset(run_dir);
  const nlohmann::json& config = d.manifest.at("config");
  const auto trajectory = config.find("trajectory");
  if (trajectory == config.end() || !trajectory->is_object() || !trajectory->contains("flow") ||
      (*trajectory)["flow"] != true)
    return 0;
  if (!d.has_sequence("trajectory")) return 0;
  return write_sequence_flow(d, "trajectory");
}

}  // namespace silva::io
