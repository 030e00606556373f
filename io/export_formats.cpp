#include "io/export_formats.hpp"

#include <cmath>

#include <opencv2/imgcodecs.hpp>

#include "core/error.hpp"
#include "core/input_limits.hpp"
#include "core/png_check.hpp"
#include "io/atomic_file.hpp"
#include "io/image_codecs.hpp"

namespace silva::io {

const std::vector<std::string>& export_format_names() {
  static const std::vector<std::string> names = {"coco-panoptic", "coco-instances", "cityscapes", "colmap",
                                                 "nerfstudio", "semantickitti", "rosbag2", "euroc",
                                                 "tartanair"};
  return names;
}

const std::string& export_format_name(ExportFormat format) { return export_format_names()[size_t(format)]; }

ExportFormat parse_export_format(const std::string& name, const std::string& where) {
  const auto& names = export_format_names();
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return ExportFormat(i);
  std::string allowed;
  for (const auto& n : names) allowed += (allowed.empty() ? "" : ", ") + n;
  throw InputError(where + ": unknown format '" + name + "' (allowed: " + allowed + ")");
}

void place_file(const std::filesystem::path& from, const std::filesystem::path& to, const ExportOptions& options) {
  require_dataset_file(from);
  if (from.extension() == ".png") {  // a truncated or damaged image is refused, not passed on
    const std::string bytes = limits::read_input_file(from, "image");
    check_png({reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()}, from.string());
  }
  if (!options.copy_files) return link_or_copy(from, to);
  std::error_code ec;
  std::filesystem::copy_file(from, to, ec);
  if (ec) throw IoError("cannot copy " + from.string() + " to " + to.string() + ": " + ec.message());
}

std::string place_coco_image(const Dataset& dataset, const DatasetFrame& f, const std::filesystem::path& images,
                             const ExportOptions& options) {
  const std::filesystem::path source = dataset.file(f, "rgb", "png");
  if (!options.jpeg_images) {
    place_file(source, images / (f.stem() + ".png"), options);
    return f.stem() + ".png";
  }
  const cv::Mat rgb = dataset.image(f, "rgb", CV_8UC3);
  std::vector<uint8_t> jpeg;
  if (!encode_image(".jpg", rgb, jpeg, {cv::IMWRITE_JPEG_QUALITY, ExportOptions::kJpegQuality}))
    throw IoError("cannot encode " + source.string() + " as JPEG");
  write_file_atomic(images / (f.stem() + ".jpg"), jpeg);
  return f.stem() + ".jpg";
}

double trajectory_camera_hz(const Dataset& d) {
  const nlohmann::json& config = d.manifest.at("config");
  const auto trajectory = config.find("trajectory");
  if (trajectory != config.end() && trajectory->is_object() && trajectory->contains("camera_hz") &&
      (*trajectory)["camera_hz"].is_number()) {
    const double hz = (*trajectory)["camera_hz"].get<double>();
    if (std::isfinite(hz) && hz > 0 && hz <= 1000) return hz;
  }
  throw InputError((d.dir / "manifest.json").string() + ": config.trajectory.camera_hz must be a number in (0, 1000]");
}

void export_dataset(const Dataset& dataset, ExportFormat format, const std::filesystem::path& out,
                    const ExportOptions& options) {
  switch (format) {
    case ExportFormat::CocoPanoptic: return export_coco_panoptic(dataset, out, options);
    case ExportFormat::CocoInstances: return export_coco_instances(dataset, out, options);
    case ExportFormat::Cityscapes: return export_cityscapes(dataset, out, options);
    case ExportFormat::Colmap: return export_colmap(dataset, out, options);
    case ExportFormat::Nerfstudio: return export_nerfstudio(dataset, out, options);
    case ExportFormat::SemanticKitti: return export_semantickitti(dataset, out, options);
    case ExportFormat::Rosbag2: return export_rosbag2(dataset, out, options);
    case ExportFormat::Euroc: return export_euroc(dataset, out, options);
    case ExportFormat::Tartanair: return export_tartanair(dataset, out, options);
  }
}

}  // namespace silva::io
