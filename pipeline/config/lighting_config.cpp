#include "pipeline/config/lighting_config.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "pipeline/config/config_value.hpp"
#include "core/error.hpp"
#include "core/input_limits.hpp"

namespace silva::pipeline {

namespace {

using render::LightingPreset;
using render::PresetFieldOf;
using render::WeatherPreset;

/// What differs between the two kinds of preset table.
template <class T>
struct PresetKind;

/// Times of day: [lighting.presets.<name>].
template <>
struct PresetKind<LightingPreset> {
  static constexpr const char* table = "lighting.presets";  ///< Where the tables live.
  static constexpr const char* base = "day";                ///< What a new name starts from.
  static auto fields() { return render::preset_fields(); }      ///< The table's keys.
  static auto builtins() { return render::builtin_presets(); }  ///< What the tables overlay.
};

/// Weathers: [lighting.weather_presets.<name>].
template <>
struct PresetKind<WeatherPreset> {
  static constexpr const char* table = "lighting.weather_presets";
  static constexpr const char* base = "clear";
  static auto fields() { return render::weather_fields(); }      ///< The table's keys.
  static auto builtins() { return render::builtin_weathers(); }  ///< What the tables overlay.
};

/// "file:line:col" of a node when toml++ knows it, else just the file.
std::string where(const std::string& file, const toml::node& node) {
  const auto& src = node.source();
  if (src.begin.line == 0) return file;
  return file + ":" + std::to_string(src.begin.line) + ":" + std::to_string(src.begin.column);
}

/// Comma-separated names of every field of T.
template <class T>
std::string allowed_keys() {
  std::string out;
  for (const PresetFieldOf<T>& f : PresetKind<T>::fields()) out += (out.empty() ? "" : ", ") + std::string(f.name);
  return out;
}

/// A number (integer or float) as a float; throws InputError naming `key` otherwise.
float read_number(const toml::node& node, const std::string& key, const std::string& at, const char* expected) {
  if (const auto* i = node.as_integer()) return float(i->get());
  if (const auto* d = node.as_floating_point()) return float(d->get());
  throw InputError(at + ": " + key + " must be " + expected + ", got " + describe_node(node));
}

/// Checks one value against the field's range.
template <class T>
void check_range(float v, const PresetFieldOf<T>& f, const std::string& key, const std::string& at) {
  if (!std::isfinite(v) || v < f.min || v > f.max) {
    std::ostringstream msg;
    msg << at << ": " << key << " = " << v << " is out of range, allowed " << f.min << " .. " << f.max;
    throw InputError(msg.str());
  }
}

/// Sets one field of `preset` from its TOML value.
template <class T>
void assign_field(T& preset, const PresetFieldOf<T>& f, const toml::node& node, const std::string& key,
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
template <class T>
void apply_table(T& preset, const toml::table& table, const std::string& name, const std::string& file) {
  for (const auto& [k, node] : table) {
    const std::string key = std::string(PresetKind<T>::table) + "." + name + "." + std::string(k.str());
    const PresetFieldOf<T>* field = nullptr;
    for (const PresetFieldOf<T>& f : PresetKind<T>::fields())
      if (k.str() == f.name) field = &f;
    if (!field)
      throw InputError(where(file, node) + ": unknown key " + key + "; allowed keys: " + allowed_keys<T>());
    assign_field(preset, *field, node, key, where(file, node));
  }
}

/// The built-ins of kind T overlaid with the tables of `presets`.
template <class T>
std::map<std::string, T> parse_tables(const toml::table& presets, const std::string& file) {
  std::map<std::string, T> out = PresetKind<T>::builtins();
  const T base = out.at(PresetKind<T>::base);
  const std::string table_name = PresetKind<T>::table;
  for (const auto& [k, node] : presets) {
    const std::string name(k.str());
    const auto* table = node.as_table();
    if (!table)
      throw InputError(where(file, node) + ": " + table_name + "." + name + " must be a table [" + table_name + "." +
                       name + "], got " + describe_node(node));
    const auto builtin = out.find(name);
    T preset = builtin != out.end() ? builtin->second : base;
    apply_table(preset, *table, name, file);
    out[name] = preset;
  }
  return out;
}

/// The built-ins of kind T overlaid with the tables under `lighting.<leaf>` of `root`.
template <class T>
std::map<std::string, T> parse_root(const toml::table& root, const std::string& file, const char* leaf) {
  const toml::node* lighting = root.get("lighting");
  if (!lighting) return PresetKind<T>::builtins();
  if (!lighting->is_table())
    throw InputError(where(file, *lighting) + ": lighting must be a table, got " + describe_node(*lighting));
  const toml::node* presets = lighting->as_table()->get(leaf);
  if (!presets) return PresetKind<T>::builtins();
  const std::string table_name = PresetKind<T>::table;
  if (!presets->is_table())
    throw InputError(where(file, *presets) + ": " + table_name + " must hold tables [" + table_name +
                     ".<name>], got " + describe_node(*presets));
  return parse_tables<T>(*presets->as_table(), file);
}

}  // namespace

toml::table read_lighting_file(const std::string& path) {
  const std::string text = limits::read_input_file(path, "lighting file");
  try {
    return toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    throw InputError(path + ":" + std::to_string(e.source().begin.line) + ": invalid TOML: " +
                     std::string(e.description()));
  }
}

std::map<std::string, LightingPreset> parse_preset_tables(const toml::table& presets, const std::string& file) {
  return parse_tables<LightingPreset>(presets, file);
}

std::map<std::string, LightingPreset> parse_lighting_presets(const toml::table& root, const std::string& file) {
  return parse_root<LightingPreset>(root, file, "presets");
}

std::map<std::string, WeatherPreset> parse_weather_tables(const toml::table& weathers, const std::string& file) {
  return parse_tables<WeatherPreset>(weathers, file);
}

std::map<std::string, WeatherPreset> parse_lighting_weathers(const toml::table& root, const std::string& file) {
  return parse_root<WeatherPreset>(root, file, "weather_presets");
}

std::map<std::string, LightingPreset> load_lighting_presets(const std::string& path) {
  return parse_lighting_presets(read_lighting_file(path), path);
}

std::map<std::string, WeatherPreset> load_lighting_weathers(const std::string& path) {
  return parse_lighting_weathers(read_lighting_file(path), path);
}

}  // namespace silva::pipeline
