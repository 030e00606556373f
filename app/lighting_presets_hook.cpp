#include "app/lighting_presets_hook.hpp"

#include "app/config_value.hpp"
#include "core/error.hpp"

namespace silva::app {

void check_lighting_presets(const toml::table& presets, const std::string& source) {
  for (const auto& [name, preset] : presets) {
    if (!preset.is_table()) {
      throw InputError(source + ": lighting.presets." + std::string(name.str()) +
                       " must be a table [lighting.presets." + std::string(name.str()) + "], got " +
                       describe_node(preset));
    }
  }
}

}  // namespace silva::app
