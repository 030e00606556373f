#include "pipeline/config/run_setup.hpp"

#include <xxhash.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "pipeline/config/config_print.hpp"
#include "pipeline/config/data_path.hpp"
#include "io/tum_trajectory_file.hpp"
#include "pipeline/config/lidar_config.hpp"
#include "pipeline/config/lighting_config.hpp"
#include "assets/load_library.hpp"
#include "core/error.hpp"
#include "io/ontology_file.hpp"
#include "io/sha256.hpp"

namespace silva::pipeline {

namespace fs = std::filesystem;

namespace {
/// Every preset of one kind a config can select: lighting.toml's (over the built-ins), then the
/// config's own `own` tables; `parse` is parse_lighting_presets or parse_lighting_weathers.
template <class Parse>
auto load_presets(const toml::table& file, const fs::path& lighting_toml, const LoadedConfig& loaded,
                  const toml::table& own, const char* leaf, Parse parse) {
  auto presets = parse(file, lighting_toml.string());
  if (!own.empty()) {
    toml::table root;
    root.insert("lighting", toml::table{{leaf, own}});
    const std::string source = loaded.source.empty() ? "--set" : loaded.source;
    for (auto& [name, preset] : parse(root, source)) presets[name] = preset;
  }
  return presets;
}

/// The weather preset `name` of `weathers`; InputError naming `key` when there is none.
template <class Map>
render::WeatherPreset find_weather(const Map& weathers, const std::string& name, const char* key) {
  const auto weather = weathers.find(name);
  if (weather == weathers.end())
    throw InputError(std::string(key) + ": no weather preset named \"" + name + "\"; define [lighting.weather_presets." +
                     name + "] or use clear, overcast, mist, rain, snow");
  return weather->second;
}

/// The preset lighting.time_of_day names with the weather lighting.weather names, the exposure,
/// and the weathers lighting.randomize draws from.
render::RunLighting selected_lighting(const LoadedConfig& loaded, const fs::path& lighting_toml) {
  const toml::table file = read_lighting_file(lighting_toml.string());
  const auto presets =
      load_presets(file, lighting_toml, loaded, loaded.lighting_presets, "presets", parse_lighting_presets);
  const auto weathers =
      load_presets(file, lighting_toml, loaded, loaded.weather_presets, "weather_presets", parse_lighting_weathers);
  const LightingConfig& choice = loaded.config.lighting;
  const auto it = presets.find(choice.time_of_day);
  if (it == presets.end())
    throw InputError("lighting.time_of_day: no preset named \"" + choice.time_of_day + "\"; define [lighting.presets." +
                     choice.time_of_day + "] or use day, dusk, night");
  render::RunLighting lighting;
  lighting.preset = it->second;
  lighting.preset.weather = find_weather(weathers, choice.weather, "lighting.weather");
  lighting.time_of_day = choice.time_of_day;
  lighting.weather = choice.weather;
  lighting.auto_exposure = choice.exposure == "auto";
  lighting.exposure_compensation_ev = float(choice.exposure_compensation);
  lighting.randomize = choice.randomize;
  if (lighting.randomize.enabled)
    for (const std::string& name : choice.randomize.weathers)
      lighting.weather_choices.push_back(find_weather(weathers, name, "lighting.randomize.weathers"));
  return lighting;
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

void load_run_files(const LoadedConfig& loaded, RunSetup& setup) {
  setup.ontology_json = data_path("configs/ontology.json");
  setup.lighting_toml = data_path("configs/lighting.toml");
  setup.ontology = io::load_ontology(setup.ontology_json);
  setup.lighting = selected_lighting(loaded, setup.lighting_toml);
  setup.lidar_toml = data_path("configs/lidar.toml");
  setup.lidar = selected_lidar_preset(loaded, setup.lidar_toml);
}

std::vector<TimedPose> trajectory_file_poses(const Config& config) {
  const auto& sequences = config.captures.sequences;
  if (config.trajectory.file.empty() || std::find(sequences.begin(), sequences.end(), "trajectory") == sequences.end())
    return {};
  return io::read_tum_trajectory(config.trajectory.file);
}

RunSetup make_run_setup(const LoadedConfig& loaded) {
  RunSetup setup;
  load_run_files(loaded, setup);
  setup.library_json = asset_library_path();
  Season season = Season::Summer;
  parse_season(loaded.config.vegetation.season, season);  // the schema allows only the season names
  setup.library = std::make_unique<assets::AssetLibrary>(assets::load_library(setup.library_json, season));
  setup.world = world::make_world_context(loaded.config, *setup.library);
  setup.world.walk_poses = trajectory_file_poses(loaded.config);
  return setup;
}

std::string resumable_config_text(const LoadedConfig& loaded) {
  LoadedConfig copy = loaded;
  copy.config.output.dir.clear();
  return config_to_toml(copy);
}

std::string run_identity_hash(const LoadedConfig& loaded, const RunSetup& setup) {
  std::string text = resumable_config_text(loaded);
  // output.formats never changes a captured file: the hash leaves its line out, so a run keeps its
  // hash whatever it exports and --resume may add or drop exports.
  const size_t formats = text.find("\nformats = ");
  if (formats != std::string::npos) text.erase(formats + 1, text.find('\n', formats + 1) - formats);
  // The contents of the files the frames depend on beyond the config: another library or an
  // edited pose file is another run.
  text += "\nasset_library " + io::sha256_file(setup.library_json);
  const CapturesConfig& captures = loaded.config.captures;
  if (std::find(captures.sequences.begin(), captures.sequences.end(), "custom") != captures.sequences.end())
    text += "\nposes_file " + io::sha256_file(captures.poses_file);
  if (!setup.world.walk_poses.empty()) text += "\ntrajectory_file " + io::sha256_file(loaded.config.trajectory.file);
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(XXH64(text.data(), text.size(), 0)));
  return buf;
}

}  // namespace silva::pipeline
