#include "io/sequence_flow.hpp"

#include <algorithm>
#include <atomic>
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

/// Writes the flow of frame `from` into frame `to` into `folders` of its sequence.
void write_flow(const Dataset& d, const DatasetFrame& from, const DatasetFrame& to, const FlowFolders& folders) {
  const FlowField flow = optical_flow(read_camera_json(d.file(from, "camera", "json")).camera, d.depth_metres(from),
                                      read_camera_json(d.file(to, "camera", "json")).camera, d.depth_metres(to));
  const fs::path seq = d.dir / from.sequence;
  write_file_atomic(seq / frame_file(folders.kitti, from.frame, "png"), encode_kitti_flow_png(flow));
  write_file_atomic(seq / frame_file(folders.flo, from.frame, "flo"), encode_middlebury_flo(flow));
  write_file_atomic(seq / frame_file(folders.mask, from.frame, "png"), encode_flow_mask_png(flow));
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
  std::atomic<int> written{0};
  tbb::parallel_for(size_t(0), frames.size(), [&](size_t i) {
    if (i + 1 < frames.size()) {
      write_flow(d, frames[i], frames[i + 1], kForwardFlow);
      written += 3;
    }
    if (i > 0) {
      write_flow(d, frames[i], frames[i - 1], kBackwardFlow);
      written += 3;
    }
  });
  return written;
}

int write_trajectory_flow(const fs::path& run_dir) {
  const Dataset d = open_dataset(run_dir);
  const nlohmann::json& config = d.manifest.at("config");
  const auto trajectory = config.find("trajectory");
  if (trajectory == config.end() || !trajectory->is_object() || !trajectory->contains("flow") ||
      (*trajectory)["flow"] != true)
    return 0;
  if (std::none_of(d.frames.begin(), d.frames.end(), [](const DatasetFrame& f) { return f.sequence == "trajectory"; }))
    return 0;
  return write_sequence_flow(d, "trajectory");
}

}  // namespace silva::io
