#pragma once
/// @file Test helper: key-by-key comparison of two Configs through the schema.
#include <string>
#include <variant>

#include "pipeline/config/config_schema.hpp"

namespace silva::pipeline::testing {

/// Names of the keys whose values differ between `a` and `b` ("" when equal).
inline std::string config_differences(Config a, Config b) {
  std::string diff;
  for (const ConfigKey& key : config_schema()) {
    const FieldRef fa = key.field(a), fb = key.field(b);
    const bool same = std::visit(
        [&](auto pa) {
          const auto pb = std::get<decltype(pa)>(fb);
          if constexpr (std::is_same_v<decltype(pa), ResolutionRef>) {
            return *pa.width == *pb.width && *pa.height == *pb.height;
          } else {
            return *pa == *pb;
          }
        },
        fa);
    if (!same) diff += std::string(key.name) + " ";
  }
  return diff;
}

}  // namespace silva::pipeline::testing
