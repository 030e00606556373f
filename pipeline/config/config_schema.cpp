#include "pipeline/config/config_schema.hpp"

#include <algorithm>
#include <cmath>

#include "core/rig_presets.hpp"
#include "core/trail_surface.hpp"
#include "pipeline/config/edit_distance.hpp"
#include "pipeline/config/number_format.hpp"

namespace silva::pipeline {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// The bounds shorthand used in the table below.
NumericRange between(double min, double max) { return {min, max, false}; }
NumericRange above(double min, double max = kInf) { return {min, max, true}; }

/// The allowed values of rig.preset: the built-in rigs' names.
std::vector<std::string_view> rig_preset_names() {
  std::vector<std::string_view> names;
  for (const RigPreset& p : rig_presets()) names.push_back(p.name);
  return names;
}

/// The allowed values of trail.surface: the families' names, then "random".
std::vector<std::string_view> trail_surface_choices() {
  std::vector<std::string_view> names(kTrailSurfaceNames.begin(), kTrailSurfaceNames.end());
  names.push_back("random");
  return names;
}

std::vector<ConfigKey> build_schema() {
  const std::vector<std::string_view> output_types = {
      "rgb", "semantic", "semantic_color", "instance", "depth", "depth_exr", "normal",
      "depth_preview", "lidar"};
  const std::vector<std::string_view> export_formats = {"coco-panoptic", "coco-instances", "cityscapes",
                                                        "colmap", "nerfstudio", "semantickitti", "rosbag2", "euroc",
                                                        "tartanair"};
  const std::vector<std::string_view> sequences = {"autopilot", "random", "custom", "trajectory"};
  using T = ValueType;
  return {
      {"seed", T::Int, "world seed; drawn from the clock when absent (printed %010d)",
       between(0, 9999999999.0), {}, [](Config& c) -> FieldRef { return &c.seed; }},
      {"output.dir", T::String, "dataset folder; a run writes <dir>/<seed>/", {}, {},
       [](Config& c) -> FieldRef { return &c.output.dir; }},
      {"output.resolution", T::Resolution, "image size in pixels, \"WxH\"", between(16, 8192), {},
       [](Config& c) -> FieldRef { return ResolutionRef{&c.output.width, &c.output.height}; }},
      {"output.types", T::StringList, "images written per capture", {}, output_types,
       [](Config& c) -> FieldRef { return &c.output.types; }},
      {"output.formats", T::StringList,
       "formats exported into <dir>/<seed>/export/<format>/ when a run completes (as silva export)", {},
       export_formats, [](Config& c) -> FieldRef { return &c.output.formats; }},
      {"lighting.time_of_day", T::String,
       "lighting preset: day, dusk, night or a [lighting.presets.<name>] of this config", {}, {},
       [](Config& c) -> FieldRef { return &c.lighting.time_of_day; }},
      {"lighting.weather", T::String,
       "weather on top of the time of day: clear, overcast, mist, rain, snow or a [lighting.weather_presets.<name>] of this config",
       {}, {}, [](Config& c) -> FieldRef { return &c.lighting.weather; }},
      {"lighting.exposure", T::String,
       "camera exposure: preset (the time of day's ev100 with the weather's offset) or auto (metered per frame: "
       "the log-average luminance of the frame exposed to mid-grey)",
       {}, {"preset", "auto"}, [](Config& c) -> FieldRef { return &c.lighting.exposure; }},
      {"lighting.exposure_compensation", T::Float, "exposure compensation, EV (positive = brighter image), either mode",
       between(-10, 10), {}, [](Config& c) -> FieldRef { return &c.lighting.exposure_compensation; }},
      {"lighting.randomize.enabled", T::Bool,
       "draw the lighting per frame from the ranges below (seeded by seed, sequence and frame; recorded in the "
       "camera file); replaces lighting.weather by a draw from lighting.randomize.weathers",
       {}, {}, [](Config& c) -> FieldRef { return &c.lighting.randomize.enabled; }},
      {"lighting.randomize.sun_elevation_deg", T::FloatList, "[min, max] of the sun's (or moon's) elevation, degrees",
       between(-10, 90), {}, [](Config& c) -> FieldRef { return &c.lighting.randomize.sun_elevation_deg; }},
      {"lighting.randomize.sun_azimuth_deg", T::FloatList,
       "[min, max] of the sun's azimuth, degrees counter-clockwise from world +X", between(-360, 360), {},
       [](Config& c) -> FieldRef { return &c.lighting.randomize.sun_azimuth_deg; }},
      {"lighting.randomize.cloud_cover", T::FloatList,
       "[min, max] of the cloud cover (1 = overcast); the drawn weather's cloud_cover_min still applies",
       between(0, 1), {}, [](Config& c) -> FieldRef { return &c.lighting.randomize.cloud_cover; }},
      {"lighting.randomize.fog_density_scale", T::FloatList,
       "[min, max] of a factor on the time of day's fog_density (before the weather's)", between(0, 100), {},
       [](Config& c) -> FieldRef { return &c.lighting.randomize.fog_density_scale; }},
      {"lighting.randomize.exposure_compensation_ev", T::FloatList,
       "[min, max] of an exposure offset added to lighting.exposure_compensation, EV (positive = brighter)",
       between(-5, 5), {}, [](Config& c) -> FieldRef { return &c.lighting.randomize.exposure_compensation_ev; }},
      {"lighting.randomize.white_balance_k", T::FloatList,
       "[min, max] of the colour temperature the camera balances for, kelvin (6504 = neutral; lower = bluer image)",
       between(2000, 20000), {}, [](Config& c) -> FieldRef { return &c.lighting.randomize.white_balance_k; }},
      {"lighting.randomize.weathers", T::StringList,
       "weather presets drawn from (built-in or [lighting.weather_presets.<name>] of this config)", {}, {},
       [](Config& c) -> FieldRef { return &c.lighting.randomize.weathers; }},
      {"lighting.randomize.weather_weights", T::FloatList,
       "relative weight of each of lighting.randomize.weathers, one per name (at least one above 0)", between(0, 1e6),
       {}, [](Config& c) -> FieldRef { return &c.lighting.randomize.weather_weights; }},
      {"captures.sequences", T::StringList, "capture sequences, in this order", {}, sequences,
       [](Config& c) -> FieldRef { return &c.captures.sequences; }},
      {"captures.random_count", T::Int, "number of random poses", between(0, 1000000), {},
       [](Config& c) -> FieldRef { return &c.captures.random_count; }},
      {"captures.autopilot_points", T::Int, "points spaced evenly along the trail",
       between(1, 1000000), {},
       [](Config& c) -> FieldRef { return &c.captures.autopilot_points; }},
      {"captures.autopilot_yaws", T::FloatList, "yaws captured at each autopilot point, degrees",
       between(-360, 360), {},
       [](Config& c) -> FieldRef { return &c.captures.autopilot_yaws; }},
      {"captures.aerial", T::Bool, "aerial perspective for autopilot and random poses", {}, {},
       [](Config& c) -> FieldRef { return &c.captures.aerial; }},
      {"captures.clearance", T::Float,
       "autopilot and random cameras keep this from every solid collision proxy, metres (poses that "
       "do not are moved)",
       between(0, 10), {}, [](Config& c) -> FieldRef { return &c.captures.clearance; }},
      {"captures.aerial_crown_clearance", T::Float,
       "aerial autopilot and random cameras keep this from every tree crown, metres",
       between(0, 20), {}, [](Config& c) -> FieldRef { return &c.captures.aerial_crown_clearance; }},
      {"captures.ground_crown_clearance", T::Float,
       "ground autopilot and random cameras keep their eye this far from every tree crown (low conifer "
       "branches), metres",
       between(0, 20), {}, [](Config& c) -> FieldRef { return &c.captures.ground_crown_clearance; }},
      {"captures.poses_file", T::String, "JSON or CSV pose file of the custom sequence (\"\" = none)",
       {}, {}, [](Config& c) -> FieldRef { return &c.captures.poses_file; }},
      {"camera.fov_deg", T::Float, "horizontal field of view, degrees", between(10, 170), {},
       [](Config& c) -> FieldRef { return &c.camera.fov_deg; }},
      {"camera.near", T::Float, "near clipping distance, metres (below camera.far)", above(0, 1e6),
       {}, [](Config& c) -> FieldRef { return &c.camera.near; }},
      {"camera.far", T::Float, "far clipping distance, metres; beyond it is background",
       above(0, 1e6), {}, [](Config& c) -> FieldRef { return &c.camera.far; }},
      {"camera.ground_height", T::Float, "ground camera height above the terrain, metres",
       above(0, 1000), {}, [](Config& c) -> FieldRef { return &c.camera.ground_height; }},
      {"camera.aerial_height", T::Float, "aerial camera height above the canopy top within 5 m (autopilot, random; else above the terrain), metres",
       above(0, 1000), {}, [](Config& c) -> FieldRef { return &c.camera.aerial_height; }},
      {"camera.aerial_pitch_deg", T::Float, "aerial camera pitch, degrees (ground pitch is 0)",
       between(-90, 90), {}, [](Config& c) -> FieldRef { return &c.camera.aerial_pitch_deg; }},
      {"camera.antialias", T::Bool, "edge antialiasing of RGB and leaf masks finer than a pixel blended to their coverage; labels and depth stay exact per pixel", {}, {},
       [](Config& c) -> FieldRef { return &c.camera.antialias; }},
      {"camera.noise", T::Bool, "shot + read sensor noise on the linear RGB signal", {}, {},
       [](Config& c) -> FieldRef { return &c.camera.noise; }},
      {"camera.full_well_e", T::Float, "sensor full-well capacity at gain 1, electrons", between(100, 1e6), {},
       [](Config& c) -> FieldRef { return &c.camera.full_well_e; }},
      {"camera.read_noise_e", T::Float, "sensor read noise std-dev, electrons", between(0, 1000), {},
       [](Config& c) -> FieldRef { return &c.camera.read_noise_e; }},
      {"camera.gain", T::Float, "analog gain (linear): full scale is full_well_e / gain electrons", between(1, 64),
       {}, [](Config& c) -> FieldRef { return &c.camera.gain; }},
      {"camera.max_gain", T::Float,
       "the auto gain's ceiling: darker scenes raise the gain to 2^(log2(f_number^2 / shutter_s) - ev100), up to this",
       between(1, 1024), {}, [](Config& c) -> FieldRef { return &c.camera.max_gain; }},
      {"camera.vignetting", T::Float, "strength of the cos^4 vignetting falloff, 0 = none, 1 = the full law",
       between(0, 1), {}, [](Config& c) -> FieldRef { return &c.camera.vignetting; }},
      {"camera.chromatic_aberration", T::Float,
       "lateral chromatic aberration: red sampled at radius x (1 - k), blue at (1 + k); 0 = none", between(0, 0.003),
       {}, [](Config& c) -> FieldRef { return &c.camera.chromatic_aberration; }},
      {"camera.bloom", T::Float,
       "share of the sky's light the lens spreads over a halo 4-64 px wide (veiling glare: bright sky glows into "
       "the leaf edges around it); 0 = none",
       between(0, 0.1), {}, [](Config& c) -> FieldRef { return &c.camera.bloom; }},
      {"camera.jpeg_quality", T::Int,
       "JPEG quality the RGB is compressed with and decoded again before it is written (a compressed camera stream); "
       "0 = none",
       between(0, 100), {}, [](Config& c) -> FieldRef { return &c.camera.jpeg_quality; }},
      {"camera.depth_of_field", T::Bool, "thin-lens depth of field (camera.f_number, focus_distance)", {}, {},
       [](Config& c) -> FieldRef { return &c.camera.depth_of_field; }},
      {"camera.f_number", T::Float, "aperture f-number of the depth of field", between(0.5, 64), {},
       [](Config& c) -> FieldRef { return &c.camera.f_number; }},
      {"camera.focus_distance", T::Float, "distance in focus, metres along the optical axis", between(0.1, 10000),
       {}, [](Config& c) -> FieldRef { return &c.camera.focus_distance; }},
      {"camera.sensor_width_mm", T::Float,
       "sensor width, millimetres; with camera.fov_deg it gives the focal length of the depth of field",
       between(1, 100), {}, [](Config& c) -> FieldRef { return &c.camera.sensor_width_mm; }},
      {"camera.motion_blur", T::Bool, "autopilot frames blurred by the camera's motion along the trail", {}, {},
       [](Config& c) -> FieldRef { return &c.camera.motion_blur; }},
      {"camera.shutter_s", T::Float, "exposure time of the motion blur, seconds", above(0, 1), {},
       [](Config& c) -> FieldRef { return &c.camera.shutter_s; }},
      {"camera.autopilot_speed", T::Float, "the autopilot camera's speed along the trail, metres per second",
       above(0, 100), {}, [](Config& c) -> FieldRef { return &c.camera.autopilot_speed; }},
      {"vegetation.density", T::Float, "percent of placement points that hold a tree",
       between(1, 25), {}, [](Config& c) -> FieldRef { return &c.vegetation.density; }},
      {"vegetation.grid_spacing", T::Float, "metres between placement points", between(0.1, 1000),
       {}, [](Config& c) -> FieldRef { return &c.vegetation.grid_spacing; }},
      {"vegetation.ground", T::Bool, "grass and ferns; false = bare ground", {}, {},
       [](Config& c) -> FieldRef { return &c.vegetation.ground; }},
      {"vegetation.season", T::String,
       "leaf colour; winter: deciduous trees and shrubs bare (labels follow: fewer canopy pixels)", {},
       {"summer", "autumn", "winter", "spring", "early_spring"}, [](Config& c) -> FieldRef { return &c.vegetation.season; }},
      {"vegetation.forest_type", T::String,
       "what grows: every species (mixed), one species' stand with its own understory, or one drawn per seed", {},
       {"mixed", "spruce_plantation", "beech_hall", "pine_heath", "random"},
       [](Config& c) -> FieldRef { return &c.vegetation.forest_type; }},
      {"terrain.max_elevation", T::Float, "terrain height amplitude, metres", between(0, 50), {},
       [](Config& c) -> FieldRef { return &c.terrain.max_elevation; }},
      {"terrain.octaves", T::Int, "simplex noise octaves", between(1, 16), {},
       [](Config& c) -> FieldRef { return &c.terrain.octaves; }},
      {"terrain.lacunarity", T::Float, "frequency factor between octaves", between(1, 8), {},
       [](Config& c) -> FieldRef { return &c.terrain.lacunarity; }},
      {"terrain.persistence", T::Float, "amplitude factor between octaves", between(0, 1), {},
       [](Config& c) -> FieldRef { return &c.terrain.persistence; }},
      {"terrain.frequency", T::Float, "base noise frequency, cycles per metre", above(0, 10), {},
       [](Config& c) -> FieldRef { return &c.terrain.frequency; }},
      {"terrain.chunk_size", T::Float,
       "chunk side, metres; a whole multiple of vertex_spacing and vegetation.grid_spacing",
       between(1, 1024), {}, [](Config& c) -> FieldRef { return &c.terrain.chunk_size; }},
      {"terrain.vertex_spacing", T::Float, "heightfield vertex spacing, metres", between(0.01, 1024),
       {}, [](Config& c) -> FieldRef { return &c.terrain.vertex_spacing; }},
      {"trail.enabled", T::Bool, "a walkable trail (needed by the autopilot sequence)", {}, {},
       [](Config& c) -> FieldRef { return &c.trail.enabled; }},
      {"trail.width", T::Float, "trail width, metres", between(0.1, 20), {},
       [](Config& c) -> FieldRef { return &c.trail.width; }},
      {"trail.control_points", T::Int, "control points of the trail's seeded walk",
       between(2, 100000), {}, [](Config& c) -> FieldRef { return &c.trail.control_points; }},
      {"trail.control_spacing", T::Float, "metres between trail control points", between(1, 1000),
       {}, [](Config& c) -> FieldRef { return &c.trail.control_spacing; }},
      {"trail.surface", T::String, "how the trail looks in RGB (labels never change): one family, or one drawn per seed", {},
       trail_surface_choices(), [](Config& c) -> FieldRef { return &c.trail.surface; }},
      {"world.extent", T::Float,
       "side of the square capture region centred on the origin, metres (the trail keeps 32 m "
       "from its edge)",
       above(64, 1e6), {}, [](Config& c) -> FieldRef { return &c.world.extent; }},
      {"world.render_distance", T::Float, "radius of the chunk cache around each camera, metres",
       above(0, 1e5), {}, [](Config& c) -> FieldRef { return &c.world.render_distance; }},
      {"render.lod", T::Bool, "level of detail by screen size; false = full detail everywhere", {},
       {}, [](Config& c) -> FieldRef { return &c.render.lod; }},
      {"render.ground_cover_distance", T::Float,
       "grass and ferns farther from the camera are not drawn (ground shows, labels follow), in every "
       "LOD mode, metres",
       above(0, 1e6), {}, [](Config& c) -> FieldRef { return &c.render.ground_cover_distance; }},
      {"trajectory.speed", T::Float, "walking speed of the trajectory sequence along the trail, metres per second",
       between(0.1, 10), {}, [](Config& c) -> FieldRef { return &c.trajectory.speed; }},
      {"trajectory.duration_s", T::Float, "length of the trajectory sequence, seconds", between(0.1, 3600), {},
       [](Config& c) -> FieldRef { return &c.trajectory.duration_s; }},
      {"trajectory.start_m", T::Float, "arc length along the trail where the trajectory starts, metres",
       between(0, 1e6), {}, [](Config& c) -> FieldRef { return &c.trajectory.start_m; }},
      {"trajectory.camera_hz", T::Float, "camera frames per second of the trajectory sequence", between(0.1, 120), {},
       [](Config& c) -> FieldRef { return &c.trajectory.camera_hz; }},
      {"trajectory.imu_hz", T::Float, "IMU samples per second (trajectory/imu.csv)", between(1, 2000), {},
       [](Config& c) -> FieldRef { return &c.trajectory.imu_hz; }},
      {"trajectory.bob_m", T::Float, "height bob of the walk, amplitude in metres", between(0, 0.5), {},
       [](Config& c) -> FieldRef { return &c.trajectory.bob_m; }},
      {"trajectory.sway_deg", T::Float, "roll sway of the walk, amplitude in degrees", between(0, 20), {},
       [](Config& c) -> FieldRef { return &c.trajectory.sway_deg; }},
      {"trajectory.step_hz", T::Float, "steps per second: the bob's frequency (the sway's is half)", between(0.1, 5), {},
       [](Config& c) -> FieldRef { return &c.trajectory.step_hz; }},
      {"trajectory.imu_noise", T::String, "IMU noise model: adis16448 (EuRoC's IMU) or none", {}, {"adis16448", "none"},
       [](Config& c) -> FieldRef { return &c.trajectory.imu_noise; }},
      {"trajectory.flow", T::Bool,
       "write the exact optical flow between consecutive trajectory frames (needs output type depth or depth_exr)", {},
       {}, [](Config& c) -> FieldRef { return &c.trajectory.flow; }},
      {"trajectory.file", T::String,
       "TUM trajectory file (t x y z qx qy qz qw per line) the walk follows instead of the trail (\"\" = the trail)",
       {}, {}, [](Config& c) -> FieldRef { return &c.trajectory.file; }},
      {"rig.preset", T::String,
       "sensor rig of every capture; fills the rig.* keys left out: mono (one camera), stereo (a rectified pair, the "
       "left the mono camera), ground_robot (a stereo pair 0.55 m up with a LiDAR), drone (one camera 3 m up, "
       "tilted 15 degrees down)",
       {}, rig_preset_names(), [](Config& c) -> FieldRef { return &c.rig.preset; }},
      {"rig.cameras", T::Int, "cameras per capture: 1, or 2 for a rectified stereo pair (the preset's unless set)",
       between(1, 2), {}, [](Config& c) -> FieldRef { return &c.rig.cameras; }},
      {"rig.baseline_m", T::Float, "stereo baseline of a two-camera rig, metres (the right camera along the left's x)",
       between(0.01, 2), {}, [](Config& c) -> FieldRef { return &c.rig.baseline_m; }},
      {"rig.height_m", T::Float,
       "ground camera height above the terrain, metres; 0 = camera.ground_height (the preset's unless set)",
       between(0, 1000), {}, [](Config& c) -> FieldRef { return &c.rig.height_m; }},
      {"rig.pitch_deg", T::Float, "ground camera tilt from level, degrees, negative = down (the preset's unless set)",
       between(-89, 89), {}, [](Config& c) -> FieldRef { return &c.rig.pitch_deg; }},
      {"rig.lidar", T::Bool, "the rig carries a LiDAR: adds output type lidar (the preset's unless set)", {}, {},
       [](Config& c) -> FieldRef { return &c.rig.lidar; }},
      {"lidar.preset", T::String,
       "LiDAR model of output type lidar: vlp16, hdl32e, hdl64e, os1_64, os1_128 (configs/lidar.toml) or a "
       "[lidar.presets.<name>] of this config", {}, {}, [](Config& c) -> FieldRef { return &c.lidar.preset; }},
      {"lidar.mount_offset", T::FloatList,
       "LiDAR origin relative to the capture camera, metres [forward, left, up] (the camera's heading)",
       between(-100, 100), {}, [](Config& c) -> FieldRef { return &c.lidar.mount_offset; }},
      {"lidar.mount_rpy_deg", T::FloatList,
       "LiDAR rotation relative to the camera's heading, degrees [roll, pitch, yaw]", between(-360, 360), {},
       [](Config& c) -> FieldRef { return &c.lidar.mount_rpy_deg; }},
      {"lidar.motion_distortion", T::Bool,
       "autopilot sweeps are cast while the sensor moves along the trail at camera.autopilot_speed (each column "
       "from its own pose; points stay in the sensor frame of each firing)",
       {}, {}, [](Config& c) -> FieldRef { return &c.lidar.motion_distortion; }},
  };
}

}  // namespace

std::string_view type_description(ValueType type) {
  switch (type) {
    case ValueType::Int: return "an integer";
    case ValueType::Float: return "a number";
    case ValueType::Bool: return "a boolean (true or false)";
    case ValueType::String: return "a string";
    case ValueType::Resolution: return "a string \"WxH\"";
    case ValueType::StringList: return "an array of strings";
    case ValueType::FloatList: return "an array of numbers";
  }
  return "a value";
}

bool NumericRange::contains(double v) const {
  if (!std::isfinite(v)) return false;
  const bool above_min = min_exclusive ? v > min : v >= min;
  return above_min && v <= max;
}

std::string NumericRange::describe() const {
  const bool has_min = std::isfinite(min);
  const bool has_max = std::isfinite(max);
  if (has_min && has_max) {
    if (min_exclusive) return "greater than " + format_number(min) + ", at most " + format_number(max);
    return format_number(min) + " to " + format_number(max);
  }
  if (has_min) return (min_exclusive ? "greater than " : "at least ") + format_number(min);
  if (has_max) return "at most " + format_number(max);
  return "any finite number";
}

std::string_view ConfigKey::section() const {
  const size_t dot = name.find('.');
  return dot == std::string_view::npos ? std::string_view{} : name.substr(0, dot);
}

std::string_view ConfigKey::leaf() const {
  const size_t dot = name.find('.');
  return dot == std::string_view::npos ? name : name.substr(dot + 1);
}

std::string ConfigKey::allowed() const {
  switch (type) {
    case ValueType::Int:
    case ValueType::Float: return range.describe();
    case ValueType::FloatList: return "each " + range.describe();
    case ValueType::Resolution: return "\"WxH\", each " + range.describe();
    case ValueType::Bool: return "true or false";
    case ValueType::String:
    case ValueType::StringList: {
      if (choices.empty()) return "any string";
      std::string text = type == ValueType::StringList ? "a subset of " : "one of ";
      for (size_t i = 0; i < choices.size(); ++i) {
        text += (i == 0 ? "" : ", ");
        text += choices[i];
      }
      return text;
    }
  }
  return {};
}

const std::vector<ConfigKey>& config_schema() {
  static const std::vector<ConfigKey> schema = build_schema();
  return schema;
}

const ConfigKey* find_key(std::string_view name) {
  for (const ConfigKey& key : config_schema()) {
    if (key.name == name) return &key;
  }
  return nullptr;
}

std::string_view replaced_key(std::string_view name) {
  if (name == "camera.film_grain")
    return "the sensor noise model replaced it: camera.noise, camera.full_well_e, camera.read_noise_e, camera.gain";
  return {};
}

std::string_view closest_key(std::string_view name) {
  std::string_view best;
  size_t best_distance = std::numeric_limits<size_t>::max();
  for (const ConfigKey& key : config_schema()) {
    // A truncated name ("camera.fov") is one step from the key it starts ("camera.fov_deg").
    const bool truncated = !name.empty() && key.name.substr(0, name.size()) == name;
    const size_t d = truncated ? 1 : edit_distance(name, key.name);
    if (d < best_distance) {
      best_distance = d;
      best = key.name;
    }
  }
  return best;
}

std::string_view closest_section(std::string_view name) {
  std::string_view best;
  size_t best_distance = std::numeric_limits<size_t>::max();
  for (const ConfigKey& key : config_schema()) {
    if (key.section().empty()) continue;  // top-level keys (seed)
    const size_t d = edit_distance(name, key.section());
    if (d < best_distance) best_distance = d, best = key.section();
  }
  return best;
}

bool is_section(std::string_view name) {
  return std::any_of(config_schema().begin(), config_schema().end(),
                     [&](const ConfigKey& key) { return !name.empty() && key.section() == name; });
}

}  // namespace silva::pipeline
