#include "pipeline/config/lidar_config.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "pipeline/config/config_value.hpp"
#include "core/error.hpp"

namespace silva::pipeline {

namespace {

/// Most beams a preset may have (channels, or entries of elevations_deg).
constexpr int kMaxChannels = 1024;

/// The keys a preset table may hold.
constexpr const char* kKeys[] = {"channels",  "elevation_min_deg", "elevation_max_deg", "elevations_deg",
                                 "columns",   "rotation_hz",       "min_range",         "max_range",
                                 "range_noise_m", "dropout",       "intensity_falloff", "intensity_noise"};

/// "file:line:col" of a node when toml++ knows it, else just the file.
std::string where(const std::string& file, const toml::node& node) {
  const auto& src = node.source();
  if (src.begin.line == 0) return file;
  return file + ":" + std::to_string(src.begin.line) + ":" + std::to_string(src.begin.column);
}

/// A number as a double within [lo, hi]; throws InputError naming `key` otherwise.
double number(const toml::node& node, const std::string& key, const std::string& at, double lo, double hi) {
  double v = 0;
  if (const auto* i = node.as_integer())
    v = double(i->get());
  else if (const auto* d = node.as_floating_point())
    v = d->get();
  else
    throw InputError(at + ": " + key + " must be a number, got " + describe_node(node));
  if (!std::isfinite(v) || v < lo || v > hi) {
    std::ostringstream msg;
    msg << at << ": " << key << " = " << v << " is out of range, allowed " << lo << " .. " << hi;
    throw InputError(msg.str());
  }
  return v;
}

/// A whole number within [lo, hi].
int whole(const toml::node& node, const std::string& key, const std::string& at, int lo, int hi) {
  if (!node.as_integer()) throw InputError(at + ": " + key + " must be a whole number, got " + describe_node(node));
  return int(number(node, key, at, lo, hi));
}

/// Overlays one preset table onto `p`.
void overlay(raycast::LidarPreset& p, const toml::table& table, const std::string& name, const std::string& file,
             bool complete) {
  const std::string prefix = "lidar.presets." + name + ".";
  std::optional<int> channels;
  std::optional<double> lo, hi;
  bool table_given = false;
  for (const auto& [k, node] : table) {
    const std::string key = prefix + std::string(k.str());
    const std::string at = where(file, node);
    const std::string_view field = k.str();
    if (field == "channels") channels = whole(node, key, at, 1, kMaxChannels);
    else if (field == "elevation_min_deg") lo = number(node, key, at, -90, 90);
    else if (field == "elevation_max_deg") hi = number(node, key, at, -90, 90);
    else if (field == "elevations_deg") {
      const toml::array* arr = node.as_array();
      if (!arr || arr->empty() || arr->size() > size_t(kMaxChannels))
        throw InputError(at + ": " + key + " must be an array of 1 to " + std::to_string(kMaxChannels) +
                         " elevations in degrees, got " + (arr ? std::to_string(arr->size()) + " entries" : describe_node(node)));
      p.elevations_deg.clear();
      for (const toml::node& e : *arr) p.elevations_deg.push_back(number(e, key, where(file, e), -90, 90));
      if (!std::is_sorted(p.elevations_deg.begin(), p.elevations_deg.end()))
        throw InputError(at + ": " + key + " must be ascending (ring 0 is the lowest beam)");
      table_given = true;
    } else if (field == "columns") p.columns = whole(node, key, at, 1, 65535);
    else if (field == "rotation_hz") p.rotation_hz = number(node, key, at, 0.1, 100);
    else if (field == "min_range") p.min_range = number(node, key, at, 0, 10000);
    else if (field == "max_range") p.max_range = number(node, key, at, 0.01, 10000);
    else if (field == "range_noise_m") p.range_noise_m = number(node, key, at, 0, 10);
    else if (field == "dropout") p.dropout = number(node, key, at, 0, 0.99);
    else if (field == "intensity_falloff") p.intensity_falloff = number(node, key, at, 0, 1);
    else if (field == "intensity_noise") p.intensity_noise = number(node, key, at, 0, 1);
    else {
      std::string allowed;
      for (const char* a : kKeys) allowed += (allowed.empty() ? "" : ", ") + std::string(a);
      throw InputError(at + ": unknown key '" + key + "' (allowed: " + allowed + ")");
    }
  }
  const std::string at = where(file, table);
  if (table_given) {
    if (channels && size_t(*channels) != p.elevations_deg.size())
      throw InputError(at + ": " + prefix + "channels = " + std::to_string(*channels) + " but elevations_deg lists " +
                       std::to_string(p.elevations_deg.size()) + " beams");
    if (lo || hi) throw InputError(at + ": lidar.presets." + name + " sets both elevations_deg and elevation_min/max_deg; use one");
  } else if (channels || lo || hi) {
    // A key left out keeps the preset's own beams: their count, lowest or highest elevation.
    if (!p.elevations_deg.empty()) {
      if (!channels) channels = int(p.elevations_deg.size());
      if (!lo) lo = p.elevations_deg.front();
      if (!hi) hi = p.elevations_deg.back();
    }
    if (!channels || !lo || !hi)
      throw InputError(at + ": lidar.presets." + name + " needs channels, elevation_min_deg and elevation_max_deg together (or elevations_deg)");
    if (*hi < *lo || (*channels == 1 && *hi != *lo))
      throw InputError(at + ": " + prefix + "elevation_max_deg must be at least elevation_min_deg (and equal for one channel)");
    p.elevations_deg.clear();
    for (int r = 0; r < *channels; ++r)
      p.elevations_deg.push_back(*channels == 1 ? *lo : *lo + (*hi - *lo) * double(r) / double(*channels - 1));
  }
  if (!complete) return;
  if (p.elevations_deg.empty())
    throw InputError(at + ": lidar.presets." + name + " has no beams: set elevations_deg, or channels with elevation_min_deg and elevation_max_deg");
  if (p.min_range >= p.max_range)
    throw InputError(at + ": " + prefix + "min_range must be below max_range");
}

}  // namespace

std::map<std::string, raycast::LidarPreset> parse_lidar_presets(const toml::table& presets, const std::string& file,
                                                                std::map<std::string, raycast::LidarPreset> base,
                                                                bool complete) {
  std::map<std::string, raycast::LidarPreset> out = base;
  for (const auto& [k, node] : presets) {
    const std::string name(k.str());
    if (!node.is_table())
      throw InputError(where(file, node) + ": lidar.presets." + name + " must be a table [lidar.presets." + name +
                       "], got " + describe_node(node));
    raycast::LidarPreset p;
    if (const auto it = base.find(name); it != base.end())
      p = it->second;
    else if (const auto v = base.find("vlp16"); v != base.end())
      p = v->second;
    p.name = name;
    overlay(p, *node.as_table(), name, file, complete);
    out[name] = p;
  }
  return out;
}

raycast::LidarPreset selected_lidar_preset(const LoadedConfig& loaded, const std::filesystem::path& lidar_toml) {
  std::error_code ec;
  if (std::filesystem::exists(lidar_toml, ec) && !std::filesystem::is_regular_file(lidar_toml, ec))
    throw InputError(lidar_toml.string() + ": the LiDAR preset file is not a regular file (a folder or device)");
  if (!std::filesystem::is_regular_file(lidar_toml, ec)) throw IoError(lidar_toml.string() + ": cannot read the LiDAR preset file");
  toml::table file;
  try {
    file = toml::parse_file(lidar_toml.string());
  } catch (const toml::parse_error& e) {
    throw InputError(lidar_toml.string() + ": " + std::string(e.description()));
  }
  const toml::table* presets = file["lidar"]["presets"].as_table();
  if (!presets) throw InputError(lidar_toml.string() + ": no [lidar.presets.<name>] tables");
  auto all = parse_lidar_presets(*presets, lidar_toml.string());
  if (!loaded.lidar_presets.empty())
    all = parse_lidar_presets(loaded.lidar_presets, loaded.source.empty() ? "--set" : loaded.source, std::move(all));
  const std::string& name = loaded.config.lidar.preset;
  const auto it = all.find(name);
  if (it == all.end()) {
    std::string allowed;
    for (const auto& [n, p] : all) allowed += (allowed.empty() ? "" : ", ") + n;
    throw InputError("lidar.preset = \"" + name + "\" is not a LiDAR preset (allowed: " + allowed +
                     ", or define [lidar.presets." + name + "])");
  }
  return it->second;
}

}  // namespace silva::pipeline
