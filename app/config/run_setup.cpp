#include "app/config/run_setup.hpp"

#include <xxhash.h>

#include <cstdio>
#include <cstdlib>

#include "app/config/config_print.hpp"
#include "app/config/data_path.hpp"
#include "app/config/lighting_config.hpp"
#include "assets/load_library.hpp"
#include "core/error.hpp"
#include "io/ontology_file.hpp"

namespace silva::app {

namespace fs = std::filesystem;

namespace {
/// Every preset a config can select: built-in, then lighting.toml, then the config's own tables.
std::map<std::string, render::LightingPreset> load_presets(const LoadedConfig& loaded, const fs::path& lighting_toml) {
  auto presets = render::builtin_presets();
  toml::table file;
  try {
    file = toml::parse_file(lighting_toml.string());
  } catch (const toml::parse_error& e) {
    throw InputError(lighting_toml.string() + ": " + std::string(e.description()));
  }
  for (auto& [name, preset] : parse_lighting_presets(file, lighting_toml.string())) presets[name] = preset;
  if (!loaded.lighting_presets.empty()) {
    toml::table root;
    root.insert("lighting", toml::table{{"presets", loaded.lighting_presets}});
    const std::string source = loaded.source.empty() ? "--set" : loaded.source;
    for (auto& [name, preset] : parse_lighting_presets(root, source)) presets[name] = preset;
  }
  return presets;
}
}  // namespace

fs::path asset_library_path() {
  const char* env = std::getenv("SILVA_ASSETS");
  const fs::path dir = env && *env ? fs::path(env) : fs::path(SILVA_ASSET_DIR);
  fs::path path = dir / "library.json";
  if (!fs::exists(path))
    throw InputError("asset library " + path.string() + " not found; run `silva assets build --out " + dir.string() +
                     "` or set SILVA_ASSETS to a folder holding library.json");
  return path;
}

RunSetup make_run_setup(const LoadedConfig& loaded) {
  RunSetup setup;
  setup.ontology_json = data_path("configs/ontology.json");
  setup.lighting_toml = data_path("configs/lighting.toml");
  setup.library_json = asset_library_path();
  setup.ontology = io::load_ontology(setup.ontology_json);
  const auto presets = load_presets(loaded, setup.lighting_toml);
  const auto it = presets.find(loaded.config.lighting.time_of_day);
  if (it == presets.end())
    throw InputError("lighting.time_of_day: no preset named \"" + loaded.config.lighting.time_of_day +
                     "\"; define [lighting.presets." + loaded.config.lighting.time_of_day + "] or use day, dusk, night");
  setup.preset = it->second;
  Season season = Season::Summer;
  parse_season(loaded.config.vegetation.season, season);  // the schema allows only the three names
  setup.library = std::make_unique<assets::AssetLibrary>(assets::load_library(setup.library_json, season));
  setup.world = world::make_world_context(loaded.config, *setup.library);
  return setup;
}

std::string config_hash(const LoadedConfig& loaded) {
  LoadedConfig copy = loaded;
  copy.config.output.dir.clear();
  const std::string text = config_to_toml(copy);
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(XXH64(text.data(), text.size(), 0)));
  return buf;
}

}  // namespace silva::app
