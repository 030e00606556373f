// TartanAir-like export (CONTRACT.md "Export formats"): per sequence the folder layout of a TartanAir trajectory,
// image_left/ (and image_right/ for a stereo rig) PNGs, depth_left/ and seg_left/ NumPy arrays, flow/ from the
// trajectory's forward flow, and pose_left.txt (pose_right.txt) in TartanAir's NED frames: the world x, −y, −z of
// Silva's Z-up world, the camera body x forward, y right, z down.
#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>
#include <Eigen/Geometry>

#include "core/error.hpp"
#include "core/input_limits.hpp"
#include "io/atomic_file.hpp"
#include "io/camera_json.hpp"
#include "io/capture_set.hpp"
#include "io/export_formats.hpp"
#include "io/npy_file.hpp"
#include "io/printf_string.hpp"

namespace silva::io {

namespace fs = std::filesystem;

namespace {

/// TartanAir's depth for pixels that hit nothing (its sky sphere's distance), metres.
constexpr float kSkyDepth = 10000.0f;

/// "NNNNNN" of frame `frame`.
std::string frame_stem(int frame) { return printf_string("%06d", frame); }

/// The .npy of a CV_32FC1 or CV_8UC1 image.
std::vector<uint8_t> image_npy(const cv::Mat& m) {
  const size_t shape[2] = {size_t(m.rows), size_t(m.cols)};
  const cv::Mat c = m.isContinuous() ? m : m.clone();
  return npy_file(m.type() == CV_32FC1 ? "<f4" : "|u1", shape, {c.data, c.total() * c.elemSize()});
}

/// A TartanAir pose line "tx ty tz qx qy qz qw" of camera_to_world `m`: position and body-to-world rotation in NED.
std::string ned_pose_line(const Mat4d& m) {
  const Mat3d world = Vec3d(1, -1, -1).asDiagonal();                               // Silva Z up -> NED
  Mat3d body;                                                                       // body axes in camera axes
  body << 0, 1, 0, 0, 0, 1, 1, 0, 0;                                                // x fwd = cam z, y = cam x, z = cam y
  const Vec3d p = world * m.block<3, 1>(0, 3);
  Eigen::Quaterniond q(Mat3d(world * m.block<3, 3>(0, 0) * body));
  q.normalize();
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  return printf_string("%.9f %.9f %.9f %.12f %.12f %.12f %.12f\n", p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), q.w());
}

/// The flow/ files of frame `f` to frame f + 1 when the sequence has its Middlebury .flo: the u, v array
/// (H x W x 2 float32) and Silva's flow state mask (H x W uint8).
void write_flow(const Dataset& d, const DatasetFrame& f, const fs::path& folder) {
  const fs::path flo = d.file(f, "flow_forward_flo", "flo");
  std::error_code ec;
  if (!fs::is_regular_file(flo, ec)) return;
  const std::string bytes = limits::read_input_file(flo, "flow file");
  const size_t pixels = size_t(d.width) * size_t(d.height);
  int32_t size[2] = {0, 0};
  if (bytes.size() == 12 + pixels * 8) std::memcpy(size, bytes.data() + 4, 8);
  if (bytes.compare(0, 4, "PIEH") != 0 || size[0] != d.width || size[1] != d.height)
    throw InputError(flo.string() + ": not a Middlebury .flo of the run's " + std::to_string(d.width) + "x" +
                     std::to_string(d.height) + " pixels");
  const size_t shape[3] = {size_t(d.height), size_t(d.width), 2};
  const std::string name = frame_stem(f.frame) + "_" + frame_stem(f.frame + 1);
  write_file_atomic(folder / (name + "_flow.npy"),
                    npy_file("<f4", shape, {reinterpret_cast<const uint8_t*>(bytes.data()) + 12, pixels * 8}));
  write_file_atomic(folder / (name + "_mask.npy"), image_npy(d.image(f, "flow_forward_mask", CV_8UC1)));
}

/// Writes one camera's image, depth and segmentation of frame `f` into `seq`'s <kind>_<side>/ folders.
void write_camera_frame(const Dataset& d, const DatasetFrame& f, bool right, const fs::path& seq,
                        const ExportOptions& options) {
  const std::string side = right ? "right" : "left", stem = frame_stem(f.frame) + "_" + side;
  place_file(d.file(f, camera_folder("rgb", right), "png"), seq / ("image_" + side) / (stem + ".png"), options);
  cv::Mat depth = d.depth_metres(f, right);
  depth.setTo(kSkyDepth, depth == std::numeric_limits<float>::infinity());
  write_file_atomic(seq / ("depth_" + side) / (stem + "_depth.npy"), image_npy(depth));
  write_file_atomic(seq / ("seg_" + side) / (stem + "_seg.npy"), image_npy(d.image(f, camera_folder("semantic", right), CV_8UC1)));
}

}  // namespace

void export_tartanair(const Dataset& d, const fs::path& out, const ExportOptions& options) {
  d.require("rgb", "tartanair");
  d.require("semantic", "tartanair");
  if (!d.has("depth_exr")) d.require("depth", "tartanair");
  const bool stereo = manifest_stereo(d.manifest);
  std::map<std::string, std::vector<DatasetFrame>> sequences;
  for (const DatasetFrame& f : d.frames) sequences[f.sequence].push_back(f);
  size_t done = 0;
  for (const auto& sequence : sequences) {
    const std::string& name = sequence.first;
    const std::vector<DatasetFrame>& frames = sequence.second;
    const fs::path seq = out / name;
    for (const bool right : {false, true}) {
      if (right && !stereo) continue;
      const std::string side = right ? "right" : "left";
      for (const std::string kind : {"image_", "depth_", "seg_"}) create_folder(seq / (kind + side));
    }
    const bool flow = d.has_sequence(name) && fs::is_directory(d.dir / name / "flow_forward_flo");
    if (flow) create_folder(seq / "flow");
    tbb::parallel_for(size_t(0), frames.size(), [&](size_t i) {
      write_camera_frame(d, frames[i], false, seq, options);
      if (stereo) write_camera_frame(d, frames[i], true, seq, options);
      if (flow) write_flow(d, frames[i], seq / "flow");
    });
    for (const bool right : {false, true}) {
      if (right && !stereo) continue;
      std::string poses;
      for (const DatasetFrame& f : frames)
        poses += ned_pose_line(read_camera_json(d.file(f, camera_folder("camera", right), "json")).camera.camera_to_world);
      write_file_atomic(seq / (right ? "pose_right.txt" : "pose_left.txt"), poses);
    }
    done += frames.size();
    if (options.progress) options.progress(done, d.frames.size());
  }
}

}  // namespace silva::io
