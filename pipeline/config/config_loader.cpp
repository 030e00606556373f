#include "pipeline/config/config_loader.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <chrono>

#include "pipeline/config/config_checks.hpp"
#include "pipeline/config/config_schema.hpp"
#include "pipeline/config/config_value.hpp"
#include "pipeline/config/lidar_config.hpp"
#include "pipeline/config/lighting_config.hpp"
#include "core/error.hpp"
#include "core/input_limits.hpp"
#include "core/rig_presets.hpp"

namespace silva::pipeline {

namespace {

constexpr std::string_view kPresetsTable = "lighting.presets";
constexpr std::string_view kWeathersTable = "lighting.weather_presets";
constexpr std::string_view kLidarTable = "lidar.presets";

/// "file:line:column" of a node parsed from a file.
std::string node_location(const std::string& source, const toml::node& node) {
  const toml::source_position begin = node.source().begin;
  if (!begin) return source;
  return source + ":" + std::to_string(begin.line) + ":" + std::to_string(begin.column);
}

/// Replaces line breaks so a message stays one line.
std::string one_line(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

/// The error for a name that is not a key: what replaced it, else the closest key ("did you mean").
[[noreturn]] void unknown_key(const std::string& where, std::string_view name) {
  if (const std::string_view note = replaced_key(name); !note.empty())
    throw InputError(where + ": key '" + std::string(name) + "' no longer exists; " + std::string(note));
  throw InputError(where + ": unknown key '" + std::string(name) + "' (did you mean '" +
                   std::string(closest_key(name)) + "'?)");
}

/// Walks a parsed table: every leaf must be a schema key; presets are kept aside.
void read_table(LoadedConfig& loaded, const toml::table& table, const std::string& prefix) {
  for (const auto& [k, node] : table) {
    const std::string name = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    const std::string where = node_location(loaded.source, node);
    if (const ConfigKey* key = find_key(name)) {
      assign_key(loaded.config, *key, node, where);
      loaded.keys_set.emplace(key->name);
      if (key->name == "seed") loaded.seed_given = true;
    } else if (name == kPresetsTable) {
      if (!node.is_table()) {
        throw InputError(where + ": lighting.presets must hold tables [lighting.presets.<name>], got " +
                         describe_node(node));
      }
      parse_preset_tables(*node.as_table(), loaded.source);  // checks every field where its source is known
      loaded.lighting_presets = *node.as_table();
    } else if (name == kWeathersTable) {
      if (!node.is_table()) {
        throw InputError(where + ": lighting.weather_presets must hold tables [lighting.weather_presets.<name>], got " +
                         describe_node(node));
      }
      parse_weather_tables(*node.as_table(), loaded.source);
      loaded.weather_presets = *node.as_table();
    } else if (name == kLidarTable) {
      if (!node.is_table())
        throw InputError(where + ": lidar.presets must hold tables [lidar.presets.<name>], got " + describe_node(node));
      parse_lidar_presets(*node.as_table(), loaded.source, {}, false);  // checks every key where its source is known
      loaded.lidar_presets = *node.as_table();
    } else if (node.is_table() && node.as_table()->empty() && !is_section(name)) {
      // An empty table sets nothing, so no key below it would be reported: name the table.
      throw InputError(where + ": unknown table [" + name + "] (the tables are sections like [" +
                       std::string(closest_section(name)) + "] and [lighting.presets.<name>])");
    } else if (node.is_table()) {
      read_table(loaded, *node.as_table(), name);
    } else if (is_section(name)) {
      throw InputError(where + ": '" + name + "' must be a table of keys [" + name + "], got " +
                       describe_node(node));
    } else {
      unknown_key(where, name);
    }
  }
}

/// A whole decimal integer (leading zeros allowed, as seeds are printed); nullopt otherwise.
std::optional<int64_t> parse_decimal(std::string_view text) {
  int64_t value = 0;
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, value);
  if (text.empty() || result.ec != std::errc{} || result.ptr != end) return std::nullopt;
  return value;
}

/// The TOML value of a command-line value, read by the key's type, stored as holder["v"].
toml::table parse_value_text(const ConfigKey& key, std::string_view value, const std::string& where) {
  const bool string_key = key.type == ValueType::String || key.type == ValueType::Resolution;
  const bool quoted = !value.empty() && (value.front() == '"' || value.front() == '\'');
  toml::table holder;
  if (string_key && !quoted) {
    holder.insert("v", std::string(value));
    return holder;
  }
  if (const auto integer = parse_decimal(value)) {
    holder.insert("v", *integer);
    return holder;
  }
  try {
    holder = toml::parse("v = " + std::string(value));
  } catch (const toml::parse_error&) {
    throw InputError(where + ": " + std::string(key.name) + " must be " +
                     std::string(type_description(key.type)) + ", got '" + std::string(value) + "'" +
                     (key.type == ValueType::StringList ? " (a TOML array, e.g. [\"rgb\",\"depth\"])" : ""));
  }
  return holder;
}

/// Sets `key` from command-line text.
void set_from_text(LoadedConfig& loaded, const ConfigKey& key, std::string_view value,
                   const std::string& where) {
  const toml::table holder = parse_value_text(key, value, where);
  assign_key(loaded.config, key, *holder.get("v"), where);
  loaded.keys_set.emplace(key.name);
  if (key.name == "seed") loaded.seed_given = true;
}

/// Fills the rig.* keys the config left out from rig.preset's values, and adds output type "lidar" to a rig that
/// carries a LiDAR.
void apply_rig_preset(LoadedConfig& loaded) {
  RigConfig& rig = loaded.config.rig;
  const RigPreset& preset = rig_preset(rig);
  const auto unset = [&](const char* key) { return loaded.keys_set.count(key) == 0; };
  if (unset("rig.cameras")) rig.cameras = preset.cameras;
  if (unset("rig.height_m")) rig.height_m = preset.height_m;
  if (unset("rig.pitch_deg")) rig.pitch_deg = preset.pitch_deg;
  if (unset("rig.lidar")) rig.lidar = preset.lidar;
  std::vector<std::string>& types = loaded.config.output.types;
  if (rig.lidar && std::find(types.begin(), types.end(), "lidar") == types.end()) types.emplace_back("lidar");
}

}  // namespace

LoadedConfig parse_config_text(std::string_view text, const std::string& source) {
  LoadedConfig loaded;
  loaded.source = source;
  toml::table table;
  try {
    table = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    const toml::source_position begin = e.source().begin;
    throw InputError(source + ":" + std::to_string(begin.line) + ":" + std::to_string(begin.column) +
                     ": invalid TOML: " + one_line(e.description()));
  }
  read_table(loaded, table, "");
  return loaded;
}

LoadedConfig read_config_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError("config file '" + path + "' not found");
  if (std::filesystem::is_directory(path, ec))
    throw InputError("config file '" + path + "' is a directory, expected a TOML file");
  return parse_config_text(limits::read_input_file(path, "config file"), path);
}

void apply_override(LoadedConfig& loaded, std::string_view assignment) {
  const std::string where = "--set " + limits::quoted_prefix(assignment);
  // One key, one value: a line break would let the text add tables of its own.
  if (assignment.find_first_of("\n\r") != std::string_view::npos)
    throw InputError(where + ": holds a line break; one --set sets one key to one value");
  const size_t eq = assignment.find('=');
  if (eq == std::string_view::npos) {
    throw InputError(where + ": expected key=value, e.g. --set camera.fov_deg=75");
  }
  std::string_view name = assignment.substr(0, eq);
  while (!name.empty() && name.back() == ' ') name.remove_suffix(1);
  const ConfigKey* key = find_key(name);
  if (key == nullptr) unknown_key(where, name);
  set_from_text(loaded, *key, assignment.substr(eq + 1), where);
}

void apply_seed_flag(LoadedConfig& loaded, std::string_view text) {
  set_from_text(loaded, *find_key("seed"), text, "--seed " + std::string(text));
}

LoadedConfig load_config(const ConfigSources& sources) {
  LoadedConfig loaded = sources.file.empty() ? LoadedConfig{} : read_config_file(sources.file);
  for (const std::string& assignment : sources.overrides) apply_override(loaded, assignment);
  if (sources.seed) apply_seed_flag(loaded, *sources.seed);
  if (sources.output_dir) loaded.config.output.dir = *sources.output_dir;
  apply_rig_preset(loaded);
  check_config(loaded);
  return loaded;
}

void resolve_seed(LoadedConfig& loaded) {
  if (loaded.seed_given) return;
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(now).count();
  loaded.config.seed = static_cast<int64_t>(static_cast<uint64_t>(ns) % 10000000000ull);
  loaded.seed_given = true;
  loaded.seed_from_clock = true;
}

}  // namespace silva::pipeline
