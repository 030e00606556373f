#include "io/label_images.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

#include "core/error.hpp"

namespace silva::io {

uint16_t depth_to_mm(float z) {
  if (!(z > 0.0f)) return 0;
  const double mm = std::round(double(z) * 1000.0);
  return uint16_t(std::clamp(mm, 1.0, 65535.0));
}

uint8_t depth_to_preview(float z) {
  if (!(z > 0.0f)) return 0;
  const double v = std::round(255.0 * std::exp(-double(z) / 10.0));
  return uint8_t(std::max(1.0, v));
}

uint8_t normal_to_byte(float n) {
  const double c = std::clamp(double(n), -1.0, 1.0);
  return uint8_t(std::round((c + 1.0) * 127.5));
}

std::vector<uint8_t> semantic_image(const LabelPlanes& g, const Ontology& ontology) {
  std::vector<uint8_t> out(g.size());
  for (size_t i = 0; i < out.size(); ++i) out[i] = ontology.id(g.role[i]);
  return out;
}

std::vector<uint8_t> semantic_color_image(const LabelPlanes& g, const Ontology& ontology) {
  std::vector<uint8_t> out(g.size() * 3);
  for (size_t i = 0; i < g.size(); ++i) {
    const auto& c = ontology.color(g.role[i]);
    out[3 * i] = c[0];
    out[3 * i + 1] = c[1];
    out[3 * i + 2] = c[2];
  }
  return out;
}

std::vector<uint16_t> depth_mm_image(const LabelPlanes& g) {
  std::vector<uint16_t> out(g.size());
  for (size_t i = 0; i < out.size(); ++i) out[i] = depth_to_mm(g.depth[i]);
  return out;
}

std::vector<uint8_t> depth_preview_image(const LabelPlanes& g) {
  std::vector<uint8_t> out(g.size());
  for (size_t i = 0; i < out.size(); ++i) out[i] = depth_to_preview(g.depth[i]);
  return out;
}

std::vector<uint8_t> normal_image(const LabelPlanes& g) {
  std::vector<uint8_t> out(g.size() * 3, 0);
  for (size_t i = 0; i < g.size(); ++i) {
    if (!(g.depth[i] > 0.0f)) continue;
    for (int a = 0; a < 3; ++a) out[3 * i + a] = normal_to_byte(g.normal[i][a]);
  }
  return out;
}

namespace {
bool carries_instance(const LabelPlanes& g, size_t i) {
  return g.instance_id[i] != 0 && role_has_instances(g.role[i]);
}
}  // namespace

InstanceImage instance_image(const LabelPlanes& g, const Ontology& ontology) {
  // Pass 1: the lowest role seen per instance id (runs of equal ids skip the map).
  std::unordered_map<uint32_t, uint8_t> lowest_role;
  uint32_t last_id = 0;
  uint8_t last_role = 0;
  for (size_t i = 0; i < g.size(); ++i) {
    if (!carries_instance(g, i)) continue;
    const uint32_t id = g.instance_id[i];
    const uint8_t role = uint8_t(g.role[i]);
    if (id == last_id && role >= last_role) continue;
    auto [it, inserted] = lowest_role.try_emplace(id, role);
    if (!inserted) it->second = std::min(it->second, role);
    last_id = id;
    last_role = it->second;
  }
  if (lowest_role.size() > 65535)
    throw InputError("a frame shows " + std::to_string(lowest_role.size()) +
                     " instances; the 16-bit instance image allows at most 65535 (lower vegetation.density)");

  InstanceImage out;
  out.entries.reserve(lowest_role.size());
  for (const auto& [id, role] : lowest_role) out.entries.push_back({0, id, ontology.id(Role(role))});
  std::sort(out.entries.begin(), out.entries.end(),
            [](const InstanceEntry& a, const InstanceEntry& b) { return a.instance_id < b.instance_id; });
  for (size_t k = 0; k < out.entries.size(); ++k) out.entries[k].index = uint16_t(k + 1);

  // Pass 2: index per pixel by binary search (again skipping runs of equal ids).
  out.pixels.assign(g.size(), 0);
  last_id = 0;
  uint16_t last_index = 0;
  for (size_t i = 0; i < g.size(); ++i) {
    if (!carries_instance(g, i)) continue;
    const uint32_t id = g.instance_id[i];
    if (id != last_id) {
      const auto it = std::lower_bound(out.entries.begin(), out.entries.end(), id,
                                       [](const InstanceEntry& e, uint32_t v) { return e.instance_id < v; });
      last_id = id;
      last_index = it->index;
    }
    out.pixels[i] = last_index;
  }
  return out;
}

std::string instance_table_json(const std::vector<InstanceEntry>& entries) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const InstanceEntry& e : entries)
    list.push_back({{"index", e.index}, {"instance_id", e.instance_id}, {"class_id", e.class_id}});
  nlohmann::ordered_json doc;
  doc["instances"] = std::move(list);
  return doc.dump(2) + "\n";
}

}  // namespace silva::io
