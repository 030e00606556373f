#pragma once
/// @file Reads a finished Silva dataset (CONTRACT.md "Dataset layout") for the exporters and the card:
/// its manifest, ontology, frame list and per-frame files.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "core/ontology.hpp"
#include "io/camera_json.hpp"
#include "io/label_images.hpp"

namespace silva::io {

/// One captured frame of a dataset.
struct DatasetFrame {
  std::string sequence;  ///< "autopilot", "random", "custom" or "trajectory".
  int frame = 0;         ///< Frame number within the sequence.
  int global_index = 0;  ///< Sequences in config order, then frame number, from 0 (CONTRACT.md --shard).
  /// "<sequence>_<frame as %06d>", the file stem the exports use.
  std::string stem() const;
};

/// A finished dataset folder <output.dir>/<seed>/ (it has manifest.json).
// NOLINTNEXTLINE(bugprone-exception-escape): nlohmann::json's destructor flattens nested values into a std::vector
struct Dataset {
  std::filesystem::path dir;        ///< The run folder.
  int64_t seed = 0;                 ///< From the manifest.
  nlohmann::json manifest;          ///< manifest.json as written by generate.
  Ontology ontology;                ///< The dataset's ontology.json.
  std::vector<std::string> types;   ///< output.types of the run.
  std::vector<DatasetFrame> frames; ///< Every frame, in global order.
  int width = 0, height = 0;        ///< output.resolution of the run: every image's size.
  /// True when the dataset has frames of `sequence` (e.g. "trajectory").
  bool has_sequence(const std::string& sequence) const;
  /// True when the run wrote output type `type` (e.g. "semantic").
  bool has(const std::string& type) const;
  /// Path of frame `f`'s file in `folder` with extension `ext`, e.g. file(f, "rgb", "png").
  std::filesystem::path file(const DatasetFrame& f, const std::string& folder, const std::string& ext) const;
  /// InputError "<dir>: <what> needs output type '<type>' ..." unless the run wrote `type`.
  void require(const std::string& type, const std::string& what) const;
  /// Frame `f`'s PNG in `folder` (e.g. "semantic") as OpenCV type `type`, checked as read_image does and against
  /// the run's resolution; for "semantic", every pixel must hold a class id of the ontology. InputError naming the
  /// file otherwise.
  cv::Mat image(const DatasetFrame& f, const std::string& folder, int type) const;
  /// Frame `f`'s depth in metres along the optical axis (CV_32FC1) of its left (or only) camera, or with `right` of
  /// a stereo rig's right camera: depth_exr when the run wrote it, else the depth PNG / 1000; +inf where nothing was
  /// hit. InputError naming the file when it is missing or not the frame's size.
  cv::Mat depth_metres(const DatasetFrame& f, bool right) const;
  /// Frame `f`'s LiDAR labels (lidar_labels/NNNNNN.label): one per point of its scan (lidar/NNNNNN.bin), each class id
  /// one of the ontology's. InputError naming the file otherwise.
  std::vector<uint32_t> lidar_labels(const DatasetFrame& f) const;
};

/// True when a manifest's config has rig.cameras = 2 (a stereo pair per capture); false for one camera or a manifest
/// from before the rig existed.
bool manifest_stereo(const nlohmann::json& manifest);

/// Opens a finished dataset: InputError naming the folder when it is not one (no .silva-run.json,
/// no manifest.json, or a malformed manifest/ontology).
Dataset open_dataset(const std::filesystem::path& dir);

/// InputError naming `path` unless it is a regular file of the dataset: missing, a symbolic link (a dataset's files
/// are never links), or a folder, FIFO or device.
void require_dataset_file(const std::filesystem::path& path);

/// Reads an image with OpenCV (IMREAD_UNCHANGED: 8/16-bit grey as one channel, colour as BGR);
/// InputError naming the file when it is not a regular file (require_dataset_file), unreadable, not of OpenCV type `type` (e.g. CV_16UC1) or,
/// when `like` is not empty, not of `like`'s size.
cv::Mat read_image(const std::filesystem::path& path, int type, const cv::Mat& like = {});

/// Reads depth_exr/NNNNNN.exr (one float32 channel, metres) through OpenCV's OpenEXR codec, which this
/// enables for the process (OPENCV_IO_ENABLE_OPENEXR) on first use; errors as read_image.
cv::Mat read_depth_exr(const std::filesystem::path& path, const cv::Mat& like = {});

/// Reads instance/NNNNNN.json: the per-frame instance table (index, instance_id, class_id); InputError
/// unless the indices are 1, 2, ... in order (CONTRACT.md).
std::vector<InstanceEntry> read_instance_table(const std::filesystem::path& path);

/// Hard-links `to` to `from` (no copy, no extra space), copying when the two are on different file
/// systems; replaces nothing (IoError when `to` exists or cannot be written).
void link_or_copy(const std::filesystem::path& from, const std::filesystem::path& to);

/// Writes `json` to `path` atomically, compact, one final newline (IoError on failure).
void write_json(const std::filesystem::path& path, const nlohmann::json& json);

/// Creates `dir` and its parents; IoError naming it when that fails.
void create_folder(const std::filesystem::path& dir);

/// Calls `fn(i)` for every frame index i of `dataset`, in parallel on the caller's TBB arena; the first
/// exception thrown is rethrown.
void for_each_frame(const Dataset& dataset, const std::function<void(size_t)>& fn);

}  // namespace silva::io
