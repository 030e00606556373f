#include "io/export_formats.hpp"

#include "core/error.hpp"

namespace silva::io {

const std::vector<std::string>& export_format_names() {
  static const std::vector<std::string> names = {"coco-panoptic", "coco-instances", "cityscapes", "colmap",
                                                 "nerfstudio", "semantickitti"};
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
  if (!options.copy_files) return link_or_copy(from, to);
  std::error_code ec;
  std::filesystem::copy_file(from, to, ec);
  if (ec) throw IoError("cannot copy " + from.string() + " to " + to.string() + ": " + ec.message());
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
  }
}

}  // namespace silva::io
