#include "pipeline/config/config_value.hpp"

#include <algorithm>
#include <charconv>
#include <sstream>

#include "pipeline/config/edit_distance.hpp"
#include "pipeline/config/number_format.hpp"
#include "core/error.hpp"

namespace silva::pipeline {

namespace {

/// Throws the wrong-type error for `key`.
[[noreturn]] void wrong_type(const ConfigKey& key, const toml::node& value, const std::string& where) {
  throw InputError(where + ": " + std::string(key.name) + " must be " +
                   std::string(type_description(key.type)) + ", got " + describe_node(value));
}

/// Throws the out-of-range error for `key` given the offending value's text.
[[noreturn]] void out_of_range(const ConfigKey& key, const std::string& value_text,
                               const std::string& where) {
  throw InputError(where + ": " + std::string(key.name) + " = " + value_text +
                   " is out of range (allowed: " + key.allowed() + ")");
}

/// A number from an integer or float node; throws the wrong-type error for anything else.
double read_number(const ConfigKey& key, const toml::node& value, const std::string& where) {
  if (const auto* i = value.as_integer()) return static_cast<double>(i->get());
  if (const auto* f = value.as_floating_point()) return f->get();
  wrong_type(key, value, where);
}

/// Checks `v` against the key's range and returns it.
double checked_number(const ConfigKey& key, double v, const std::string& where) {
  if (!key.range.contains(v)) out_of_range(key, format_number(v), where);
  return v;
}

/// Checks a string against the key's choices (if any), suggesting the closest one.
void check_choice(const ConfigKey& key, const std::string& s, const std::string& where) {
  if (key.choices.empty() ||
      std::find(key.choices.begin(), key.choices.end(), s) != key.choices.end()) {
    return;
  }
  const auto closest = std::min_element(
      key.choices.begin(), key.choices.end(),
      [&](std::string_view a, std::string_view b) { return edit_distance(s, a) < edit_distance(s, b); });
  throw InputError(where + ": " + std::string(key.name) + ": \"" + s + "\" is not allowed (" +
                   key.allowed() + "; did you mean \"" + std::string(*closest) + "\"?)");
}

/// Parses a whole decimal number made only of digits; false when `text` is anything else.
bool parse_digits(std::string_view text, int64_t& out) {
  if (text.empty() || text.size() > 9) return false;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), out);
  return result.ec == std::errc{} && result.ptr == text.data() + text.size();
}

void assign_resolution(const ConfigKey& key, ResolutionRef ref, const toml::node& value,
                       const std::string& where) {
  const auto* s = value.as_string();
  if (s == nullptr) wrong_type(key, value, where);
  const std::string_view text = s->get();
  const size_t x = text.find('x');
  int64_t w = 0, h = 0;
  if (x == std::string_view::npos || !parse_digits(text.substr(0, x), w) ||
      !parse_digits(text.substr(x + 1), h)) {
    throw InputError(where + ": " + std::string(key.name) + " must be \"WxH\" (e.g. \"1920x1080\"), got " +
                     describe_node(value));
  }
  if (!key.range.contains(double(w)) || !key.range.contains(double(h))) {
    out_of_range(key, "\"" + std::string(text) + "\"", where);
  }
  *ref.width = static_cast<int>(w);
  *ref.height = static_cast<int>(h);
}

void assign_string_list(const ConfigKey& key, std::vector<std::string>& out, const toml::node& value,
                        const std::string& where) {
  const auto* array = value.as_array();
  if (array == nullptr) wrong_type(key, value, where);
  std::vector<std::string> items;
  for (const toml::node& element : *array) {
    const auto* s = element.as_string();
    if (s == nullptr) wrong_type(key, value, where);
    check_choice(key, s->get(), where);
    if (std::find(items.begin(), items.end(), s->get()) != items.end()) {
      throw InputError(where + ": " + std::string(key.name) + " lists \"" + s->get() + "\" twice");
    }
    items.push_back(s->get());
  }
  out = std::move(items);
}

void assign_number_list(const ConfigKey& key, std::vector<double>& out, const toml::node& value,
                        const std::string& where) {
  const auto* array = value.as_array();
  if (array == nullptr) wrong_type(key, value, where);
  std::vector<double> items;
  for (const toml::node& element : *array) {
    if (!element.is_number()) wrong_type(key, value, where);
    items.push_back(checked_number(key, read_number(key, element, where), where));
  }
  out = std::move(items);
}

}  // namespace

std::string describe_node(const toml::node& node) {
  std::ostringstream text;
  switch (node.type()) {
    case toml::node_type::string: text << "a string (\"" << node.as_string()->get() << "\")"; break;
    case toml::node_type::integer: text << "an integer (" << *node.as_integer() << ")"; break;
    case toml::node_type::floating_point: text << "a float (" << *node.as_floating_point() << ")"; break;
    case toml::node_type::boolean: text << "a boolean (" << *node.as_boolean() << ")"; break;
    case toml::node_type::array: text << "an array"; break;
    case toml::node_type::table: text << "a table"; break;
    default: text << "a date/time (" << toml::toml_formatter{node} << ")"; break;
  }
  return text.str();
}

void assign_key(Config& config, const ConfigKey& key, const toml::node& value,
                const std::string& where) {
  const FieldRef field = key.field(config);
  switch (key.type) {
    case ValueType::Int: {
      const auto* i = value.as_integer();
      if (i == nullptr) wrong_type(key, value, where);
      if (!key.range.contains(double(i->get()))) out_of_range(key, std::to_string(i->get()), where);
      if (auto* p64 = std::get_if<int64_t*>(&field)) **p64 = i->get();
      else **std::get_if<int*>(&field) = static_cast<int>(i->get());
      return;
    }
    case ValueType::Float:
      *std::get<double*>(field) = checked_number(key, read_number(key, value, where), where);
      return;
    case ValueType::Bool: {
      const auto* b = value.as_boolean();
      if (b == nullptr) wrong_type(key, value, where);
      *std::get<bool*>(field) = b->get();
      return;
    }
    case ValueType::String: {
      const auto* s = value.as_string();
      if (s == nullptr) wrong_type(key, value, where);
      check_choice(key, s->get(), where);
      *std::get<std::string*>(field) = s->get();
      return;
    }
    case ValueType::Resolution:
      assign_resolution(key, std::get<ResolutionRef>(field), value, where);
      return;
    case ValueType::StringList:
      assign_string_list(key, *std::get<std::vector<std::string>*>(field), value, where);
      return;
    case ValueType::FloatList:
      assign_number_list(key, *std::get<std::vector<double>*>(field), value, where);
      return;
  }
}

}  // namespace silva::pipeline
