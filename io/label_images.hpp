#pragma once
/// @file Per-pixel encodings of a G-buffer into label and depth images (CONTRACT.md "File formats").
/// Every function is a pure function of its inputs; images are row-major, width*height pixels.
#include <cstdint>
#include <string>
#include <vector>

#include "core/ontology.hpp"
#include "io/label_planes.hpp"

namespace silva::io {

/// depth PNG value: clamp(round(z*1000), 1, 65535) for a hit (z > 0), 0 for no hit.
uint16_t depth_to_mm(float z);

/// depth_preview value: max(1, round(255*exp(-z/10))) for a hit (z > 0), 0 for no hit.
uint8_t depth_to_preview(float z);

/// normal PNG channel: round((n+1)*127.5), n clamped to [-1, 1].
uint8_t normal_to_byte(float n);

/// semantic: the ontology class id of each pixel's role.
std::vector<uint8_t> semantic_image(const LabelPlanes& g, const Ontology& ontology);

/// semantic_color: interleaved R, G, B ontology colour of each pixel's role.
std::vector<uint8_t> semantic_color_image(const LabelPlanes& g, const Ontology& ontology);

/// depth: 16-bit millimetres per depth_to_mm (the G-buffer already holds 0 beyond camera far).
std::vector<uint16_t> depth_mm_image(const LabelPlanes& g);

/// depth_preview: 8-bit white-near grey per depth_to_preview.
std::vector<uint8_t> depth_preview_image(const LabelPlanes& g);

/// normal: interleaved R, G, B = normal_to_byte of world normal x, y, z; (0, 0, 0) for no hit.
std::vector<uint8_t> normal_image(const LabelPlanes& g);

/// One row of the per-frame instance table.
struct InstanceEntry {
  uint16_t index = 0;        ///< Value in the instance PNG (1, 2, ...).
  uint32_t instance_id = 0;  ///< Packed world instance id (core/instance_id.hpp).
  uint8_t class_id = 0;      ///< Ontology class id of the instance's pixels.
  friend bool operator==(const InstanceEntry&, const InstanceEntry&) = default;
};

/// The instance image of a frame and its table.
struct InstanceImage {
  std::vector<uint16_t> pixels;        ///< Per-frame index, 0 = none.
  std::vector<InstanceEntry> entries;  ///< Ascending instance_id; entries[k].index == k + 1.
};

/// Builds the instance image: pixels whose role has instances (core role_has_instances) and a
/// non-zero instance_id get the index of that id; indices 1, 2, ... follow ascending instance_id.
/// An instance whose pixels show several roles takes the class of the lowest role value.
/// Throws InputError when more than 65535 instances are visible in the frame.
InstanceImage instance_image(const LabelPlanes& g, const Ontology& ontology);

/// instance/NNNNNN.json text: {"instances": [{"index", "instance_id", "class_id"}, ...]}.
std::string instance_table_json(const std::vector<InstanceEntry>& entries);

}  // namespace silva::io
