#include "pipeline/config/config_checks.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "pipeline/config/lighting_config.hpp"
#include "pipeline/config/number_format.hpp"
#include "core/error.hpp"

namespace silva::pipeline {

namespace {

constexpr int64_t kMaxFramesPerSequence = 1000000;  // frame files are numbered with six digits

bool contains(const std::vector<std::string>& list, std::string_view item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

void check_multiple(const std::string& where, double chunk_size, std::string_view part_key,
                    double part) {
  if (!is_whole_multiple(chunk_size, part)) {
    throw InputError(where + ": terrain.chunk_size = " + format_number(chunk_size) +
                     " must be a whole multiple of " + std::string(part_key) + " = " +
                     format_number(part));
  }
}

/// [lighting.randomize]: every range is [min, max] with min <= max; each weather is a weather preset with one
/// weight, and the weights do not all vanish.
void check_lighting_randomize(const std::string& where, const LightingRandomizeConfig& r,
                              const std::vector<std::string>& weathers) {
  const std::pair<const char*, const std::vector<double>*> ranges[] = {
      {"sun_elevation_deg", &r.sun_elevation_deg}, {"sun_azimuth_deg", &r.sun_azimuth_deg},
      {"cloud_cover", &r.cloud_cover}, {"fog_density_scale", &r.fog_density_scale},
      {"exposure_compensation_ev", &r.exposure_compensation_ev}, {"white_balance_k", &r.white_balance_k}};
  for (const auto& [key, range] : ranges) {
    const std::string name = std::string("lighting.randomize.") + key;
    if (range->size() != 2)
      throw InputError(where + ": " + name + " must list 2 numbers [min, max], got " + std::to_string(range->size()));
    if ((*range)[0] > (*range)[1])
      throw InputError(where + ": " + name + " = [" + format_number((*range)[0]) + ", " + format_number((*range)[1]) +
                       "] must have min <= max");
  }
  for (const std::string& name : r.weathers)
    if (!contains(weathers, name))
      throw InputError(where + ": lighting.randomize.weathers names \"" + name +
                       "\", which is not a weather preset (define [lighting.weather_presets." + name + "])");
  if (r.weather_weights.size() != r.weathers.size())
    throw InputError(where + ": lighting.randomize.weather_weights must list one weight per name of "
                             "lighting.randomize.weathers (" + std::to_string(r.weathers.size()) + "), got " +
                     std::to_string(r.weather_weights.size()));
  double total = 0;
  for (const double w : r.weather_weights) total += w;
  if (!r.weathers.empty() && !(total > 0))
    throw InputError(where + ": lighting.randomize.weather_weights must hold at least one weight above 0");
}

}  // namespace

bool is_whole_multiple(double whole, double part) {
  const double ratio = whole / part;
  const double n = std::round(ratio);
  return n >= 1 && std::fabs(ratio - n) <= 1e-9 * n;
}

std::vector<std::string> lighting_preset_names(const LoadedConfig& loaded) {
  std::vector<std::string> names;
  for (const auto& [name, preset] : parse_preset_tables(loaded.lighting_presets, loaded.source)) {
    names.push_back(name);
  }
  return names;
}

/// Lying snow (a weather whose snow_cover is above 0: lighting.weather, or a weather lighting.randomize may
/// draw) needs vegetation.season = "winter": snow on leafy crowns is no real look, and the season, which
/// shapes the world, is not the weather's to change.
void check_snow_season(const std::string& where, const Config& c,
                       const std::map<std::string, render::WeatherPreset>& presets) {
  if (c.vegetation.season == "winter") return;
  const auto snowy = [&](const std::string& name) {
    const auto it = presets.find(name);
    return it != presets.end() && it->second.snow_cover > 0.0f;
  };
  const LightingRandomizeConfig& r = c.lighting.randomize;
  std::string key;
  if (!r.enabled && snowy(c.lighting.weather)) key = "lighting.weather = \"" + c.lighting.weather + "\"";
  for (size_t i = 0; r.enabled && key.empty() && i < r.weathers.size(); ++i)
    if (snowy(r.weathers[i]) && r.weather_weights[i] > 0.0) key = "lighting.randomize.weathers's \"" + r.weathers[i] + "\"";
  if (!key.empty())
    throw InputError(where + ": " + key + " lays snow, which needs vegetation.season = \"winter\" (got \"" +
                     c.vegetation.season + "\"): bare deciduous crowns; snow on leaves is no real look");
}

void check_config(const LoadedConfig& loaded) {
  const Config& c = loaded.config;
  const std::string where = loaded.source.empty() ? std::string("config") : loaded.source;
  if (c.output.dir.empty()) throw InputError(where + ": output.dir must not be empty");
  if (!(c.camera.near < c.camera.far)) {
    throw InputError(where + ": camera.near = " + format_number(c.camera.near) +
                     " must be less than camera.far = " + format_number(c.camera.far));
  }
  if (c.camera.depth_of_field) {
    constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
    const double focal_m = c.camera.sensor_width_mm * 1e-3 / (2.0 * std::tan(0.5 * c.camera.fov_deg * kDegToRad));
    if (!(c.camera.focus_distance > focal_m)) {
      throw InputError(where + ": camera.focus_distance = " + format_number(c.camera.focus_distance) +
                       " must exceed the lens's focal length, " + format_number(focal_m) +
                       " m (from camera.sensor_width_mm and camera.fov_deg)");
    }
  }
  if (contains(c.output.formats, "semantickitti") && !contains(c.output.types, "lidar"))
    throw InputError(where + ": output.formats has \"semantickitti\", which needs \"lidar\" in output.types");
  check_multiple(where, c.terrain.chunk_size, "terrain.vertex_spacing", c.terrain.vertex_spacing);
  check_multiple(where, c.terrain.chunk_size, "vegetation.grid_spacing", c.vegetation.grid_spacing);
  if (contains(c.output.formats, "euroc") && !contains(c.captures.sequences, "trajectory"))
    throw InputError(where + ": output.formats has \"euroc\", which needs \"trajectory\" in captures.sequences");
  if (c.trajectory.flow && !contains(c.output.types, "depth") && !contains(c.output.types, "depth_exr"))
    throw InputError(where + ": trajectory.flow = true needs \"depth\" or \"depth_exr\" in output.types");
  const auto& sequences = c.captures.sequences;
  if (contains(sequences, "custom") && c.captures.poses_file.empty()) {
    throw InputError(where + ": captures.sequences has \"custom\", which needs captures.poses_file");
  }
  if (sequences.empty()) {
    throw InputError(where + ": captures.sequences is empty (allowed: one or more of autopilot, "
                             "random, custom, trajectory)");
  }
  const bool autopilot = contains(sequences, "autopilot") && c.trail.enabled;
  const bool trajectory = contains(sequences, "trajectory") && (c.trail.enabled || !c.trajectory.file.empty());
  if (!autopilot && !trajectory && !contains(sequences, "random") && !contains(sequences, "custom")) {
    throw InputError(where + ": the autopilot and trajectory sequences need trail.enabled = true, and no other "
                             "sequence is left in captures.sequences");
  }
  if (autopilot && c.captures.autopilot_yaws.empty()) {
    throw InputError(where + ": captures.autopilot_yaws must list at least one yaw for the "
                             "autopilot sequence");
  }
  const int64_t autopilot_frames =
      int64_t{c.captures.autopilot_points} * int64_t(c.captures.autopilot_yaws.size());
  if (autopilot && autopilot_frames > kMaxFramesPerSequence) {
    throw InputError(where + ": captures.autopilot_points x len(captures.autopilot_yaws) = " +
                     std::to_string(autopilot_frames) + " frames, allowed at most 1000000");
  }
  for (const auto& [key, values] : {std::pair<const char*, const std::vector<double>*>{"lidar.mount_offset", &c.lidar.mount_offset},
                                    {"lidar.mount_rpy_deg", &c.lidar.mount_rpy_deg}})
    if (values->size() != 3)
      throw InputError(where + ": " + key + " must list 3 numbers, got " + std::to_string(values->size()));
  const std::vector<std::string> presets = lighting_preset_names(loaded);
  if (!contains(presets, c.lighting.time_of_day)) {
    std::string allowed;
    for (const std::string& name : presets) allowed += (allowed.empty() ? "" : ", ") + name;
    throw InputError(where + ": lighting.time_of_day = \"" + c.lighting.time_of_day +
                     "\" is not a preset (allowed: " + allowed +
                     ", or define [lighting.presets." + c.lighting.time_of_day + "])");
  }
  const auto weather_presets = parse_weather_tables(loaded.weather_presets, loaded.source);
  std::vector<std::string> weathers;
  for (const auto& [name, weather] : weather_presets) weathers.push_back(name);
  if (!contains(weathers, c.lighting.weather)) {
    std::string allowed;
    for (const std::string& name : weathers) allowed += (allowed.empty() ? "" : ", ") + name;
    throw InputError(where + ": lighting.weather = \"" + c.lighting.weather + "\" is not a weather preset (allowed: " +
                     allowed + ", or define [lighting.weather_presets." + c.lighting.weather + "])");
  }
  check_lighting_randomize(where, c.lighting.randomize, weathers);
  check_snow_season(where, c, weather_presets);
}

}  // namespace silva::pipeline
