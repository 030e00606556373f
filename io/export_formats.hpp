#pragma once
/// @file The formats `silva export` converts a finished dataset into (CONTRACT.md "Export formats"),
/// one source file per format. Each exporter writes into an existing empty folder, reads the dataset's
/// files only (nothing is rendered again), works on frames in parallel on the caller's TBB arena and
/// writes the same bytes for any thread count. Source images are hard-linked (copied across file systems), or
/// copied with ExportOptions::copy_files.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "io/dataset_reader.hpp"

namespace silva::io {

/// An export format.
enum class ExportFormat { CocoPanoptic, CocoInstances, Cityscapes, Colmap, Nerfstudio, SemanticKitti, Rosbag2, Euroc, Tartanair };

/// Every format's name, in ExportFormat order: coco-panoptic, coco-instances, cityscapes, colmap, nerfstudio,
/// semantickitti, rosbag2, euroc, tartanair.
const std::vector<std::string>& export_format_names();

/// The name of `format`.
const std::string& export_format_name(ExportFormat format);

/// How an export places the dataset's files it takes over unchanged (images, scans, calibration), and which
/// instances the COCO exports mark as crowd fragments.
struct ExportOptions {
  bool copy_files = false;  ///< Copy them (edits of the export leave the dataset alone) instead of hard-linking.
  /// Instances covering fewer pixels in a frame are iscrowd 1 in the COCO exports (fragments a detector should
  /// neither learn nor be scored on); 0 marks none.
  int64_t min_instance_area = kDefaultMinInstanceArea;
  /// The default min_instance_area (pixels): below a 4 x 4 patch.
  static constexpr int64_t kDefaultMinInstanceArea = 16;
  /// The COCO exports' images as JPEG (quality kJpegQuality, written as images/<stem>.jpg, as detectron2's COCO
  /// panoptic loader looks for them) instead of the dataset's PNGs.
  bool jpeg_images = false;
  /// JPEG quality of jpeg_images.
  static constexpr int kJpegQuality = 95;
  /// The Cityscapes split folder the frames go into: "train", "val" or "test".
  std::string cityscapes_split = "train";
  /// Called with (frames done, frames in all) by a streaming export (rosbag2): with 0 as it starts, then as it
  /// completes each frame; may be empty.
  std::function<void(size_t, size_t)> progress;
};

/// The stamp step of the rosbag2 export's still captures: frame n of a sequence is stamped n x 0.1 s.
inline constexpr uint64_t kRosbagFramePeriodNs = 100'000'000;

/// Places frame `f`'s RGB image into `images` as the COCO exports name it (<stem>.png, or <stem>.jpg with
/// options.jpeg_images) and returns that file name.
std::string place_coco_image(const Dataset& dataset, const DatasetFrame& f, const std::filesystem::path& images,
                             const ExportOptions& options);

/// Places the dataset file `from` at `to`: a hard link (a copy across file systems), or a copy with
/// options.copy_files. InputError when `from` is not a regular file of the dataset or, for a PNG, fails check_png
/// (truncated or damaged); IoError when neither link nor copy can be made.
void place_file(const std::filesystem::path& from, const std::filesystem::path& to, const ExportOptions& options);

/// The trajectory sequence's camera rate (config.trajectory.camera_hz of the manifest); InputError naming the
/// manifest unless it is a number in (0, 1000].
double trajectory_camera_hz(const Dataset& dataset);

/// Parses a format name; InputError "<where>: unknown format 'x' (allowed: ...)" otherwise.
ExportFormat parse_export_format(const std::string& name, const std::string& where);

/// Writes `dataset` as `format` into the empty folder `out`. InputError when the dataset lacks an output
/// type the format needs; IoError when a file cannot be written.
void export_dataset(const Dataset& dataset, ExportFormat format, const std::filesystem::path& out,
                    const ExportOptions& options = {});

/// COCO panoptic: images/, panoptic/<stem>.png (segment id = R + 256 G + 65536 B) and panoptic.json.
void export_coco_panoptic(const Dataset& dataset, const std::filesystem::path& out, const ExportOptions& options);
/// COCO instances (detection): images/ and instances.json with compressed RLE masks, bboxes and areas.
void export_coco_instances(const Dataset& dataset, const std::filesystem::path& out, const ExportOptions& options);
/// Cityscapes: leftImg8bit/train/<seed>/ and gtFine/train/<seed>/ (labelIds, instanceIds, color).
void export_cityscapes(const Dataset& dataset, const std::filesystem::path& out, const ExportOptions& options);
/// COLMAP text model: sparse/0/{cameras,images,points3D}.txt and images/.
void export_colmap(const Dataset& dataset, const std::filesystem::path& out, const ExportOptions& options);
/// nerfstudio / instant-ngp / 3DGS: transforms.json (OpenGL camera axes), images/, depth/, masks/.
void export_nerfstudio(const Dataset& dataset, const std::filesystem::path& out, const ExportOptions& options);
/// EuRoC / ASL (visual-inertial odometry): the trajectory sequence as mav0/{cam0,imu0,state_groundtruth_estimate0}/.
void export_euroc(const Dataset& dataset, const std::filesystem::path& out, const ExportOptions& options);
/// TartanAir-like (visual odometry, stereo, flow): per sequence image_left/, depth_left/ and seg_left/ (NumPy), the
/// right camera's for a stereo rig, flow/ from the forward flow, and pose_left.txt in NED frames.
void export_tartanair(const Dataset& dataset, const std::filesystem::path& out, const ExportOptions& options);
/// SemanticKITTI (LiDAR): sequences/NN/{velodyne,labels,image_2}/, calib.txt, poses.txt, times.txt and
/// semantic-kitti.yaml, the label map.
void export_semantickitti(const Dataset& dataset, const std::filesystem::path& out, const ExportOptions& options);
/// ROS 2 bags: per sequence a folder <sequence>/ with <sequence>_0.mcap (CDR messages, ros2msg schemas) and
/// metadata.yaml, so `ros2 bag play <out>/<sequence>` replays it; streamed frame by frame.
void export_rosbag2(const Dataset& dataset, const std::filesystem::path& out, const ExportOptions& options);

}  // namespace silva::io
