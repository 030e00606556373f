#include "io/capture_set.hpp"

#include <tbb/parallel_for.h>

#include <cstdio>
#include <stdexcept>

#include "io/exr_writer.hpp"
#include "io/label_images.hpp"
#include "io/png_writer.hpp"

namespace silva::io {

namespace {

std::vector<uint8_t> bytes_of(const std::string& text) { return std::vector<uint8_t>(text.begin(), text.end()); }

/// Encodes one output type into its file(s).
std::vector<EncodedFile> encode_one(OutputType t, const LabelPlanes& g, std::span<const uint8_t> rgb,
                                    const Ontology& ontology, int frame, bool right) {
  const int w = g.width, h = g.height;
  const std::string folder = camera_folder(output_type_name(t), right);
  auto png = [&](std::vector<uint8_t> bytes) {
    return std::vector<EncodedFile>{{frame_file(folder, frame, "png"), std::move(bytes)}};
  };
  switch (t) {
    case OutputType::Rgb:
      return png(encode_png_rgb8(rgb, w, h));
    case OutputType::Semantic:
      return png(encode_png_grey8(semantic_image(g, ontology), w, h));
    case OutputType::SemanticColor:
      return png(encode_png_rgb8(semantic_color_image(g, ontology), w, h));
    case OutputType::Instance: {
      const InstanceImage inst = instance_image(g, ontology);
      return {{frame_file(folder, frame, "png"), encode_png_grey16(inst.pixels, w, h)},
              {frame_file(folder, frame, "json"), bytes_of(instance_table_json(inst.entries))}};
    }
    case OutputType::Depth:
      return png(encode_png_grey16(depth_mm_image(g), w, h));
    case OutputType::DepthExr:
      return {{frame_file(folder, frame, "exr"), encode_exr_y(g.depth, w, h)}};
    case OutputType::DepthPreview:
      return png(encode_png_grey8(depth_preview_image(g), w, h));
    case OutputType::Normal:
      return png(encode_png_rgb8(normal_image(g), w, h));
    case OutputType::Lidar:
      return {};  // cast and encoded from the sweep, not the G-buffer (systems/cast_lidar.hpp)
  }
  throw std::logic_error("encode_one: unknown output type");
}

}  // namespace

std::string frame_file(const std::string& folder, int frame, const std::string& ext) {
  char name[16];
  std::snprintf(name, sizeof name, "%06d", frame);
  return folder + "/" + name + "." + ext;
}

std::string camera_folder(const std::string& name, bool right) { return right ? name + "_right" : name; }

std::vector<std::string> frame_file_names(const OutputSelection& selection, int frame, bool stereo) {
  std::vector<std::string> names;
  for (const bool right : {false, true}) {
    if (right && !stereo) break;
    for (int k = 0; k < kOutputTypeCount; ++k) {
      const OutputType t = OutputType(k);
      if (!selection.has(t) || (right && t == OutputType::Lidar)) continue;
      if (t == OutputType::Lidar) {  // the sweep's scan and labels (systems/cast_lidar.hpp), left camera only
        names.push_back(frame_file("lidar", frame, "bin"));
        names.push_back(frame_file("lidar_labels", frame, "label"));
        names.push_back(frame_file("lidar_labels", frame, "json"));
        continue;
      }
      const std::string folder = camera_folder(output_type_name(t), right);
      names.push_back(frame_file(folder, frame, t == OutputType::DepthExr ? "exr" : "png"));
      if (t == OutputType::Instance) names.push_back(frame_file(folder, frame, "json"));
    }
  }
  if (stereo) {
    names.push_back(frame_file("camera_right", frame, "json"));
    names.push_back(frame_file("disparity", frame, "png"));
  }
  return names;
}

EncodedSet encode_capture_set(const LabelPlanes& gbuffer, std::span<const uint8_t> rgb, const Ontology& ontology,
                              const OutputSelection& selection, int frame, bool right) {
  std::vector<OutputType> todo;
  for (int t = 0; t < kOutputTypeCount; ++t)
    if (selection.has(OutputType(t))) todo.push_back(OutputType(t));
  std::vector<std::vector<EncodedFile>> parts(todo.size());
  tbb::parallel_for(size_t(0), todo.size(), [&](size_t k) { parts[k] = encode_one(todo[k], gbuffer, rgb, ontology, frame, right); });
  EncodedSet out;
  for (auto& files : parts)
    for (auto& f : files) out.push_back(std::move(f));
  return out;
}

}  // namespace silva::io
