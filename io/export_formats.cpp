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

void export_dataset(const Dataset& dataset, ExportFormat format, const std::filesystem::path& out) {
  switch (format) {
    case ExportFormat::CocoPanoptic: return export_coco_panoptic(dataset, out);
    case ExportFormat::CocoInstances: return export_coco_instances(dataset, out);
    case ExportFormat::Cityscapes: return export_cityscapes(dataset, out);
    case ExportFormat::Colmap: return export_colmap(dataset, out);
    case ExportFormat::Nerfstudio: return export_nerfstudio(dataset, out);
    case ExportFormat::SemanticKitti: return export_semantickitti(dataset, out);
  }
}

}  // namespace silva::io
