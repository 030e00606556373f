#include "pipeline/config/config_print.hpp"

#include <cstdio>
#include <sstream>

#include "pipeline/config/config_schema.hpp"
#include "pipeline/config/number_format.hpp"

namespace silva::pipeline {

namespace {

/// One key's value as TOML text.
std::string toml_value(const ConfigKey& key, Config& config) {
  const FieldRef field = key.field(config);
  switch (key.type) {
    case ValueType::Int:
      if (const auto* p64 = std::get_if<int64_t*>(&field)) return std::to_string(**p64);
      return std::to_string(**std::get_if<int*>(&field));
    case ValueType::Float: return format_toml_float(*std::get<double*>(field));
    case ValueType::Bool: return *std::get<bool*>(field) ? "true" : "false";
    case ValueType::String: return toml_quote(*std::get<std::string*>(field));
    case ValueType::Resolution: {
      const ResolutionRef r = std::get<ResolutionRef>(field);
      return toml_quote(std::to_string(*r.width) + "x" + std::to_string(*r.height));
    }
    case ValueType::StringList: {
      std::string text = "[";
      for (const std::string& s : *std::get<std::vector<std::string>*>(field)) {
        text += (text.size() > 1 ? ", " : "") + toml_quote(s);
      }
      return text + "]";
    }
    case ValueType::FloatList: {
      std::string text = "[";
      for (double v : *std::get<std::vector<double>*>(field)) {
        text += (text.size() > 1 ? ", " : "") + format_toml_float(v);
      }
      return text + "]";
    }
  }
  return {};
}

/// One key's value as JSON.
nlohmann::json json_value(const ConfigKey& key, Config& config) {
  const FieldRef field = key.field(config);
  return std::visit([](auto p) -> nlohmann::json {
    if constexpr (std::is_pointer_v<decltype(p)>) {
      return *p;
    } else {
      return std::to_string(*p.width) + "x" + std::to_string(*p.height);
    }
  }, field);
}

/// A key of a preset table, quoted when it is not a bare TOML key.
std::string toml_key(std::string_view key) {
  const bool bare = !key.empty() && key.find_first_not_of(
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_-") == std::string_view::npos;
  return bare ? std::string(key) : toml_quote(key);
}

/// The entries of a preset table as `dotted.key = value` lines (nested tables as dotted keys).
void print_table_entries(std::ostringstream& out, const toml::table& table, const std::string& prefix) {
  for (const auto& [k, node] : table) {
    const std::string key = prefix + toml_key(k.str());
    if (const auto* sub = node.as_table()) {
      print_table_entries(out, *sub, key + ".");
    } else {
      out << key << " = ";
      out << toml::toml_formatter{node} << "\n";
    }
  }
}

}  // namespace

std::string toml_quote(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
          char escape[8];
          std::snprintf(escape, sizeof(escape), "\\u%04x", static_cast<unsigned>(c));
          out += escape;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string config_to_toml(const LoadedConfig& loaded) {
  Config config = loaded.config;
  std::ostringstream out;
  out << "# Silva resolved config: every key (documented in configs/default.toml).\n";
  if (loaded.seed_from_clock) out << "# The seed was drawn from the clock.\n";
  std::string_view section = "";
  for (const ConfigKey& key : config_schema()) {
    if (key.section() != section) {
      section = key.section();
      out << "\n[" << section << "]\n";
    }
    out << key.leaf() << " = " << toml_value(key, config) << "  # " << key.help << "\n";
  }
  for (const auto& [name, preset] : loaded.lighting_presets) {
    out << "\n[lighting.presets." << toml_key(name.str()) << "]\n";
    if (const auto* table = preset.as_table()) print_table_entries(out, *table, "");
  }
  for (const auto& [name, weather] : loaded.weather_presets) {
    out << "\n[lighting.weather_presets." << toml_key(name.str()) << "]\n";
    if (const auto* table = weather.as_table()) print_table_entries(out, *table, "");
  }
  for (const auto& [name, preset] : loaded.lidar_presets) {
    out << "\n[lidar.presets." << toml_key(name.str()) << "]\n";
    if (const auto* table = preset.as_table()) print_table_entries(out, *table, "");
  }
  return out.str();
}

nlohmann::json config_to_json(const LoadedConfig& loaded) {
  Config config = loaded.config;
  nlohmann::json out = nlohmann::json::object();
  for (const ConfigKey& key : config_schema()) {
    nlohmann::json* node = &out;  // a dotted name nests: lighting.randomize.enabled -> lighting: {randomize: {enabled}}
    std::string_view name = key.name;
    for (size_t dot = name.find('.'); dot != std::string_view::npos; dot = name.find('.')) {
      node = &(*node)[std::string(name.substr(0, dot))];
      name.remove_prefix(dot + 1);
    }
    (*node)[std::string(name)] = json_value(key, config);
  }
  if (!loaded.lighting_presets.empty()) {
    std::ostringstream presets;
    presets << toml::json_formatter{loaded.lighting_presets};
    out["lighting"]["presets"] = nlohmann::json::parse(presets.str());
  }
  if (!loaded.weather_presets.empty()) {
    std::ostringstream weathers;
    weathers << toml::json_formatter{loaded.weather_presets};
    out["lighting"]["weather_presets"] = nlohmann::json::parse(weathers.str());
  }
  if (!loaded.lidar_presets.empty()) {
    std::ostringstream presets;
    presets << toml::json_formatter{loaded.lidar_presets};
    out["lidar"]["presets"] = nlohmann::json::parse(presets.str());
  }
  return out;
}

}  // namespace silva::pipeline
