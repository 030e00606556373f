#include "io/dataset_reader.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <system_error>

#include <opencv2/imgcodecs.hpp>
#include <tbb/parallel_for.h>

#include "core/error.hpp"
#include "core/input_limits.hpp"
#include "core/png_check.hpp"
#include "io/atomic_file.hpp"
#include "io/capture_set.hpp"
#include "io/image_codecs.hpp"
#include "io/json_read.hpp"
#include "io/lidar_files.hpp"
#include "io/ontology_file.hpp"
#include "io/run_folder.hpp"

namespace silva::io {

namespace fs = std::filesystem;

std::string DatasetFrame::stem() const {
  char buf[16];
  std::snprintf(buf, sizeof buf, "_%06d", frame);
  return sequence + buf;
}

bool Dataset::has(const std::string& type) const {
  return std::find(types.begin(), types.end(), type) != types.end();
}

fs::path Dataset::file(const DatasetFrame& f, const std::string& folder, const std::string& ext) const {
  return dir / f.sequence / frame_file(folder, f.frame, ext);
}

bool Dataset::has_sequence(const std::string& sequence) const {
  return std::any_of(frames.begin(), frames.end(), [&](const DatasetFrame& f) { return f.sequence == sequence; });
}

void Dataset::require(const std::string& type, const std::string& what) const {
  if (!has(type))
    throw InputError(dir.string() + ": " + what + " needs output type '" + type +
                     "', which this dataset's output.types does not hold");
}

namespace {

/// The manifest's value at the dotted `path` as T; InputError naming the path unless it is there and `kind`.
template <class T>
T manifest_value(const nlohmann::json& manifest, const std::string& path, const std::string& where, const char* kind) {
  const nlohmann::json* v = &manifest;
  std::stringstream keys(path);
  for (std::string key; std::getline(keys, key, '.');) {
    if (!v->is_object() || !v->contains(key)) throw InputError(where + ": " + path + " is missing");
    v = &(*v)[key];
  }
  try {
    return v->get<T>();
  } catch (const nlohmann::json::exception&) {
    throw InputError(where + ": " + path + " must be " + kind);
  }
}

/// Which class ids (0 ... 255) the ontology defines.
std::array<bool, 256> class_ids(const Ontology& ontology) {
  std::array<bool, 256> known{};
  for (const OntologyClass& c : ontology.classes) known[c.id] = true;
  return known;
}

}  // namespace

Dataset open_dataset(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw InputError(dir.string() + ": not a Silva dataset folder (expected <output.dir>/<seed>/)");
  if (!read_run_marker(dir))
    throw InputError(dir.string() + ": not a Silva dataset (no .silva-run.json; expected <output.dir>/<seed>/)");
  if (!fs::exists(dir / "manifest.json", ec))
    throw InputError(dir.string() + ": not a finished Silva dataset (no manifest.json: finish it with "
                     "generate --resume, or silva merge for shards)");
  Dataset d;
  d.dir = dir;
  const std::string where = (dir / "manifest.json").string();
  d.manifest = parse_json_text(read_text_file(dir / "manifest.json"), where);
  d.seed = manifest_value<int64_t>(d.manifest, "seed", where, "a whole number");
  d.types = manifest_value<std::vector<std::string>>(d.manifest, "config.output.types", where, "a list of names");
  const auto sequences =
      manifest_value<std::vector<std::string>>(d.manifest, "config.captures.sequences", where, "a list of names");
  const auto resolution = manifest_value<std::string>(d.manifest, "config.output.resolution", where, "\"WxH\"");
  if (std::sscanf(resolution.c_str(), "%dx%d", &d.width, &d.height) != 2 || d.width < 1 || d.height < 1 ||
      d.width > 8192 || d.height > 8192)
    throw InputError(where + ": config.output.resolution '" + limits::quoted_prefix(resolution) +
                     "' is not WxH within 1 ... 8192");
  const auto counts = manifest_value<nlohmann::json>(d.manifest, "frames", where, "an object");
  if (!counts.is_object()) throw InputError(where + ": frames must be an object of counts per sequence");
  int global = 0;
  for (const std::string& s : sequences) {
    const int n = counts.contains(s) ? int(json_int(counts, s, 0, limits::kMaxFramesPerSequence, where + ": frames"))
                                     : 0;
    // The count is only trusted as far as the files go: its last camera file must be there.
    const fs::path last = dir / s / frame_file("camera", n - 1, "json");
    if (n > 0 && !fs::is_regular_file(last, ec))
      throw InputError(where + ": frames." + s + " = " + std::to_string(n) + ", but " + last.string() +
                       " is missing (a damaged or unfinished dataset)");
    for (int f = 0; f < n; ++f) d.frames.push_back({s, f, global++});
  }
  d.ontology = load_ontology(dir / "ontology.json");
  return d;
}

void require_dataset_file(const fs::path& path) {
  std::error_code ec;
  const fs::file_status link = fs::symlink_status(path, ec);
  if (!fs::exists(link)) throw InputError(path.string() + ": missing from the dataset");
  if (fs::is_symlink(link))
    throw InputError(path.string() + ": is a symbolic link; a dataset's files are regular files it wrote itself");
  if (!fs::is_regular_file(link)) throw InputError(path.string() + ": not a regular file (a folder, FIFO or device)");
}

cv::Mat read_image(const fs::path& path, int type, const cv::Mat& like) {
  require_dataset_file(path);
  cv::Mat image;
  if (path.extension() == ".png") {  // checked first: libpng prints its own error line on corrupt data
    std::string bytes = limits::read_input_file(path, "image");
    check_png({reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()}, path.string());
    image = decode_image(cv::Mat(1, int(bytes.size()), CV_8U, bytes.data()), cv::IMREAD_UNCHANGED);
  } else {
    image = read_image_file(path.string(), cv::IMREAD_UNCHANGED);
  }
  if (image.empty()) throw InputError(path.string() + ": not a readable image");
  if (image.type() != type)
    throw InputError(path.string() + ": not a Silva image of this kind (" + std::to_string(image.channels()) +
                     " channels of " + std::to_string(image.elemSize1() * 8) + " bits)");
  if (!like.empty() && image.size() != like.size())
    throw InputError(path.string() + ": " + std::to_string(image.cols) + "x" + std::to_string(image.rows) +
                     ", not the frame's " + std::to_string(like.cols) + "x" + std::to_string(like.rows));
  return image;
}

cv::Mat Dataset::image(const DatasetFrame& f, const std::string& folder, int type) const {
  const fs::path path = file(f, folder, "png");
  cv::Mat m = read_image(path, type, cv::Mat(height, width, CV_8UC1));
  if (folder == "semantic") {
    const std::array<bool, 256> known = class_ids(ontology);
    for (int y = 0; y < m.rows; ++y) {
      const uint8_t* row = m.ptr<uint8_t>(y);
      for (int x = 0; x < m.cols; ++x)
        if (!known[row[x]])
          throw InputError(path.string() + ": pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") holds class " +
                           std::to_string(row[x]) + ", which ontology.json does not define");
    }
  }
  return m;
}

bool manifest_stereo(const nlohmann::json& manifest) {
  const nlohmann::json& config = manifest.at("config");
  if (!config.contains("rig") || !config.at("rig").is_object()) return false;
  const nlohmann::json& rig = config.at("rig");
  return rig.contains("cameras") && rig.at("cameras").is_number_integer() && rig.at("cameras").get<int64_t>() == 2;
}

cv::Mat Dataset::depth_metres(const DatasetFrame& f, bool right) const {
  cv::Mat m;
  if (has("depth_exr")) {
    m = read_depth_exr(file(f, camera_folder("depth_exr", right), "exr"), cv::Mat(height, width, CV_8UC1));
  } else {
    image(f, camera_folder("depth", right), CV_16UC1).convertTo(m, CV_32FC1, 1.0 / 1000.0);
  }
  m.setTo(std::numeric_limits<float>::infinity(), m == 0.0f);
  return m;
}

std::vector<uint32_t> Dataset::lidar_labels(const DatasetFrame& f) const {
  const fs::path scan = file(f, "lidar", "bin"), path = file(f, "lidar_labels", "label");
  require_dataset_file(scan);
  require_dataset_file(path);
  std::vector<uint32_t> labels = read_semantic_kitti_labels(path);
  std::error_code ec;
  const uintmax_t points = fs::file_size(scan, ec) / 16;
  if (ec || labels.size() != points)
    throw InputError(path.string() + ": " + std::to_string(labels.size()) + " labels for the " + std::to_string(points) +
                     " points of " + scan.filename().string());
  const std::array<bool, 256> known = class_ids(ontology);
  for (size_t i = 0; i < labels.size(); ++i)
    if ((labels[i] & 0xFFFFu) > 255 || !known[labels[i] & 0xFFu])
      throw InputError(path.string() + ": point " + std::to_string(i) + " holds class " +
                       std::to_string(labels[i] & 0xFFFFu) + ", which ontology.json does not define");
  return labels;
}

cv::Mat read_depth_exr(const fs::path& path, const cv::Mat& like) {
  // OpenCV reads the variable when it first decodes an EXR; Silva's own files are the only EXRs it reads.
  static const bool enabled = setenv("OPENCV_IO_ENABLE_OPENEXR", "1", 1) == 0;
  (void)enabled;
  return read_image(path, CV_32FC1, like);
}

std::vector<InstanceEntry> read_instance_table(const fs::path& path) {
  const std::string where = path.string();
  const nlohmann::json j = parse_json_text(read_text_file(path), where);
  std::vector<InstanceEntry> entries;
  for (const nlohmann::json& e : json_member(j, "instances", where)) {
    const long long next = (long long)entries.size() + 1;
    entries.push_back({uint16_t(json_int(e, "index", next, next, where)),
                       uint32_t(json_int(e, "instance_id", 1, UINT32_MAX, where)),
                       uint8_t(json_int(e, "class_id", 0, 255, where))});
  }
  return entries;
}

void link_or_copy(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::create_hard_link(from, to, ec);
  if (!ec) return;
  ec.clear();
  fs::copy_file(from, to, ec);
  if (ec) throw IoError("cannot link or copy " + from.string() + " to " + to.string() + ": " + ec.message());
}

void write_json(const fs::path& path, const nlohmann::json& json) { write_file_atomic(path, json.dump() + "\n"); }

void create_folder(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw IoError("cannot create folder " + dir.string() + ": " + ec.message());
}

void for_each_frame(const Dataset& dataset, const std::function<void(size_t)>& fn) {
  tbb::parallel_for(size_t(0), dataset.frames.size(), [&](size_t i) { fn(i); });
}

}  // namespace silva::io
