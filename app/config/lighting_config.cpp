#include "app/config/lighting_config.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "app/config/config_value.hpp"
#include "core/error.hpp"

namespace silva::app {

namespace {

using render::LightingPreset;
using render::PresetField;

/// "file:line:col" of a node when toml++ knows it, else just the file.
std::string where(const std::string& file, const toml::node& node) {
  const auto& src = node.source();
  if (src.begin.line == 0) return file;
  return file + ":" + std::to_string(src.begin.line) + ":" + std::to_string(src.begin.column);
}

/// Comma-separated names of every preset field.
std::string allowed_keys() {
  std::string out;
  for (const PresetField& f : render::preset_fields()) out += (out.empty() ? "" : ", ") + std::string(f.name);
  return out;
}

/// A number (integer or float) as a float; throws InputError naming `key` otherwise.
float read_number(const toml::node& node, const std::string& key, const std::string& at, const char* expected) {
  if (const auto* i = node.as_integer()) return float(i->get());
  if (const auto* d = node.as_floating_point()) return float(d->get());
  throw InputError(at + ": " + key + " must be " + expected + ", got " + describe_node(node));
}

/// Checks one value against the field's range.
void check_range(float v, const PresetField& f, const std::string& key, const std::string& at) {
  if (!std::isfinite(v) || v < f.min || v > f.max) {
    std::ostringstream msg;
    msg << at << ": " << key << " = " << v << " is out of range, allowed " << f.min << " .. " << f.max;
    throw InputError(msg.str());
  }
}

/// Sets one field of `preset` from its TOML value.
void assign_field(LightingPreset& preset, const PresetField& f, const toml::node& node, const std::string& key,
                  const std::string& at) {
  if (f.scalar) {
    const float v = read_number(node, key, at, "a number");
    check_range(v, f, key, at);
    preset.*f.scalar = v;
    return;
  }
  const char* expected = "an array of 3 numbers [r, g, b]";
  const auto* arr = node.as_array();
  if (!arr || arr->size() != 3) throw InputError(at + ": " + key + " must be " + expected + ", got " + describe_node(node));
  render::Rgb c{};
  for (size_t k = 0; k < 3; ++k) {
    c[k] = read_number(*arr->get(k), key, at, expected);
    check_range(c[k], f, key, at);
  }
  preset.*f.colour = c;
}

/// Applies every key of one preset table on top of `preset`.
void apply_table(LightingPreset& preset, const toml::table& table, const std::string& name, const std::string& file) {
  const auto fields = render::preset_fields();
  for (const auto& [k, node] : table) {
    const std::string key = "lighting.presets." + name + "." + std::string(k.str());
    const PresetField* field = nullptr;
    for (const PresetField& f : fields)
      if (k.str() == f.name) field = &f;
    if (!field)
      throw InputError(where(file, node) + ": unknown key " + key + "; allowed keys: " + allowed_keys());
    assign_field(preset, *field, node, key, where(file, node));
  }
}

}  // namespace

std::map<std::string, LightingPreset> parse_preset_tables(const toml::table& presets, const std::string& file) {
  std::map<std::string, LightingPreset> out = render::builtin_presets();
  const LightingPreset day = out.at("day");
  for (const auto& [k, node] : presets) {
    const std::string name(k.str());
    const auto* table = node.as_table();
    if (!table)
      throw InputError(where(file, node) + ": lighting.presets." + name + " must be a table [lighting.presets." + name +
                       "], got " + describe_node(node));
    const auto builtin = out.find(name);
    LightingPreset preset = builtin != out.end() ? builtin->second : day;
    apply_table(preset, *table, name, file);
    out[name] = preset;
  }
  return out;
}

std::map<std::string, LightingPreset> parse_lighting_presets(const toml::table& root, const std::string& file) {
  const toml::node* lighting = root.get("lighting");
  if (!lighting) return render::builtin_presets();
  if (!lighting->is_table())
    throw InputError(where(file, *lighting) + ": lighting must be a table, got " + describe_node(*lighting));
  const toml::node* presets = lighting->as_table()->get("presets");
  if (!presets) return render::builtin_presets();
  if (!presets->is_table())
    throw InputError(where(file, *presets) + ": lighting.presets must hold tables [lighting.presets.<name>], got " +
                     describe_node(*presets));
  return parse_preset_tables(*presets->as_table(), file);
}

std::map<std::string, LightingPreset> load_lighting_presets(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw IoError(path + ": cannot read the lighting file");
  toml::table root;
  try {
    root = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    throw InputError(path + ":" + std::to_string(e.source().begin.line) + ": invalid TOML: " +
                     std::string(e.description()));
  }
  return parse_lighting_presets(root, path);
}

}  // namespace silva::app
