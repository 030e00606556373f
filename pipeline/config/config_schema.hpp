#pragma once
/// @file The config schema: one row per key of CONTRACT.md "Config keys". Parsing, type and
/// range checks, --set overrides, the printed config and unknown-key suggestions all use it.
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/config.hpp"

namespace silva::pipeline {

/// The TOML type a key takes (Resolution is a "WxH" string stored as two ints).
enum class ValueType { Int, Float, Bool, String, Resolution, StringList, FloatList };

/// Human name of a type for messages: "an integer", "a float", "an array of strings", ...
std::string_view type_description(ValueType type);

/// Bounds of a numeric key (of each element for FloatList); max is always inclusive.
struct NumericRange {
  double min = -std::numeric_limits<double>::infinity();  ///< Lower bound.
  double max = std::numeric_limits<double>::infinity();   ///< Upper bound (inclusive).
  bool min_exclusive = false;                              ///< True: value must exceed min.
  /// True when `v` is finite and inside the bounds.
  bool contains(double v) const;
  /// The allowed range as text: "10 to 170", "greater than 0", "at least 1", "0 to 9999999999".
  std::string describe() const;
};

/// Where a "WxH" key stores its two numbers.
struct ResolutionRef {
  int* width;   ///< W
  int* height;  ///< H
};

/// A writable reference to the Config field a key sets; the alternative matches the key's type.
using FieldRef = std::variant<int64_t*, int*, double*, bool*, std::string*, ResolutionRef,
                              std::vector<std::string>*, std::vector<double>*>;

/// One config key.
struct ConfigKey {
  std::string_view name;                  ///< Dotted name, e.g. "camera.fov_deg".
  ValueType type;                         ///< TOML type.
  std::string_view help;                  ///< One-line help, printed as a comment.
  NumericRange range;                     ///< Int/Float/FloatList (element) bounds; Resolution: W and H.
  std::vector<std::string_view> choices;  ///< String/StringList: allowed values (empty = any).
  FieldRef (*field)(Config&);             ///< The Config field this key sets.
  /// Section part of the name ("camera"), empty for top-level keys ("seed").
  std::string_view section() const;
  /// Name inside its section ("fov_deg").
  std::string_view leaf() const;
  /// What values are allowed, as text for messages and comments.
  std::string allowed() const;
};

/// Every config key, in printing order (top-level keys first, then sections as in CONTRACT.md).
const std::vector<ConfigKey>& config_schema();

/// The key with this dotted name, or nullptr.
const ConfigKey* find_key(std::string_view name);

/// For a key that no longer exists, what replaced it (one line); empty for any other name.
std::string_view replaced_key(std::string_view name);

/// The valid key closest to `name` by edit distance (ties: first in schema order).
std::string_view closest_key(std::string_view name);

/// True when `name` is a section of the schema ("camera", "output", ...).
bool is_section(std::string_view name);

/// The section ("camera") closest to `name` by edit distance.
std::string_view closest_section(std::string_view name);

}  // namespace silva::pipeline
