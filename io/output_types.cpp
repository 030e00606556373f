#include "io/output_types.hpp"

#include "core/error.hpp"

namespace silva::io {

namespace {
constexpr const char* kNames[kOutputTypeCount] = {"rgb",   "semantic",  "semantic_color", "instance",
                                                  "depth", "depth_exr", "depth_preview",  "normal", "lidar"};
}  // namespace

const char* output_type_name(OutputType t) { return kNames[size_t(t)]; }

OutputSelection OutputSelection::all() {
  OutputSelection s;
  s.enabled.fill(true);
  return s;
}

OutputSelection OutputSelection::from_names(const std::vector<std::string>& names, const std::string& key) {
  OutputSelection s;
  for (const std::string& name : names) {
    int found = -1;
    for (int t = 0; t < kOutputTypeCount; ++t)
      if (name == kNames[t]) found = t;
    if (found < 0) {
      std::string allowed;
      for (int t = 0; t < kOutputTypeCount; ++t) allowed += std::string(t ? ", " : "") + kNames[t];
      throw InputError(key + ": unknown output type \"" + name + "\"; allowed: " + allowed);
    }
    if (s.enabled[size_t(found)]) throw InputError(key + ": output type \"" + name + "\" is listed twice");
    s.enabled[size_t(found)] = true;
  }
  return s;
}

}  // namespace silva::io
