#pragma once
/// @file The fully resolved run configuration (CONTRACT.md "Config keys"), as plain data.
/// app/ parses TOML + --set overrides into this struct; every other folder only reads it.
#include <cstdint>
#include <string>
#include <vector>

namespace silva {

/// Output images and settings (`[output]`).
struct OutputConfig {
  std::string dir = "out";                 ///< output.dir
  int width = 1920;                        ///< output.resolution (W)
  int height = 1080;                       ///< output.resolution (H)
  std::vector<std::string> types = {"rgb", "semantic", "semantic_color", "instance",
                                    "depth", "depth_exr", "normal"};  ///< output.types
  std::vector<std::string> formats;        ///< output.formats: exports written after the run
};

/// Per-frame lighting randomisation (`[lighting.randomize]`): each range is [min, max], drawn uniformly per frame.
struct LightingRandomizeConfig {
  bool enabled = false;                                   ///< lighting.randomize.enabled
  std::vector<double> sun_elevation_deg = {15, 70};       ///< lighting.randomize.sun_elevation_deg
  std::vector<double> sun_azimuth_deg = {0, 360};         ///< lighting.randomize.sun_azimuth_deg
  std::vector<double> cloud_cover = {0, 0.8};             ///< lighting.randomize.cloud_cover
  std::vector<double> fog_density_scale = {0.5, 2};       ///< lighting.randomize.fog_density_scale
  std::vector<double> exposure_compensation_ev = {-0.5, 0.5};  ///< lighting.randomize.exposure_compensation_ev
  std::vector<double> white_balance_k = {5500, 7500};     ///< lighting.randomize.white_balance_k
  std::vector<std::string> weathers = {"clear", "overcast", "mist", "rain"};  ///< lighting.randomize.weathers
  std::vector<double> weather_weights = {4, 2, 1, 1};     ///< lighting.randomize.weather_weights
};

/// Lighting selection (`[lighting]`); the presets themselves live in render::LightingPreset.
struct LightingConfig {
  std::string time_of_day = "day";  ///< lighting.time_of_day: preset name
  std::string weather = "clear";    ///< lighting.weather: weather preset name
  std::string exposure = "preset";  ///< lighting.exposure: "preset" (the preset's ev100) or "auto" (metered)
  double exposure_compensation = 0; ///< lighting.exposure_compensation: EV, positive = brighter
  LightingRandomizeConfig randomize;  ///< [lighting.randomize]
};

/// Capture sequences (`[captures]`).
struct CapturesConfig {
  std::vector<std::string> sequences = {"autopilot", "random"};  ///< captures.sequences
  int random_count = 100;                          ///< captures.random_count
  int autopilot_points = 230;                      ///< captures.autopilot_points
  std::vector<double> autopilot_yaws = {-45, 0, 45};  ///< captures.autopilot_yaws (degrees)
  bool aerial = false;                             ///< captures.aerial
  std::string poses_file;                          ///< captures.poses_file ("" = none)
  double clearance = 1.0;                          ///< captures.clearance (m)
  double aerial_crown_clearance = 2.0;             ///< captures.aerial_crown_clearance (m)
  double ground_crown_clearance = 0.5;             ///< captures.ground_crown_clearance (m)
};

/// Camera model and post (`[camera]`).
struct CameraConfig {
  double fov_deg = 90;            ///< camera.fov_deg (horizontal)
  double near = 0.05;             ///< camera.near (m)
  double far = 150;               ///< camera.far (m)
  double ground_height = 1.5;     ///< camera.ground_height (m above ground)
  double aerial_height = 10;      ///< camera.aerial_height (m above the canopy top, or the ground)
  double aerial_pitch_deg = -45;  ///< camera.aerial_pitch_deg
  bool antialias = true;          ///< camera.antialias: edge filter on RGB (labels stay exact)
  bool noise = true;              ///< camera.noise: shot + read sensor noise on RGB
  double full_well_e = 10000;     ///< camera.full_well_e (electrons at full scale, gain 1)
  double read_noise_e = 3;        ///< camera.read_noise_e (electrons, std-dev)
  double gain = 2;                ///< camera.gain (analog gain, linear, in bright light)
  double max_gain = 32;           ///< camera.max_gain (the auto gain's ceiling in dark scenes)
  double vignetting = 0.25;       ///< camera.vignetting (strength of the cos^4 falloff)
  double chromatic_aberration = 0;  ///< camera.chromatic_aberration (lateral, fraction of the radius)
  double bloom = 0.03;            ///< camera.bloom (share of the sky's light the lens spreads into a halo)
  int jpeg_quality = 0;           ///< camera.jpeg_quality (0 = the RGB is not JPEG-compressed)
  bool depth_of_field = false;    ///< camera.depth_of_field: thin-lens blur
  double f_number = 2;            ///< camera.f_number (aperture)
  double focus_distance = 3;      ///< camera.focus_distance (m along the optical axis)
  double sensor_width_mm = 11.3;  ///< camera.sensor_width_mm (gives the focal length in mm)
  bool motion_blur = false;       ///< camera.motion_blur: autopilot frames blurred along the trail
  double shutter_s = 0.01;        ///< camera.shutter_s (exposure time for motion blur)
  double autopilot_speed = 1.4;   ///< camera.autopilot_speed (m/s along the trail)
};

/// Vegetation placement (`[vegetation]`).
struct VegetationConfig {
  double density = 5;         ///< vegetation.density: percent of placement points holding a tree (1..25)
  double grid_spacing = 2.0;  ///< vegetation.grid_spacing (m)
  bool ground = true;         ///< vegetation.ground: grass/ferns on/off
  std::string season = "summer";  ///< vegetation.season: summer, autumn or winter
  std::string forest_type = "mixed";  ///< vegetation.forest_type: a world/forest_types.hpp name or "random"
};

/// Terrain heightfield (`[terrain]`).
struct TerrainConfig {
  double max_elevation = 1.5;   ///< terrain.max_elevation (m)
  int octaves = 6;              ///< terrain.octaves
  double lacunarity = 2.0;      ///< terrain.lacunarity
  double persistence = 0.5;     ///< terrain.persistence
  double frequency = 0.01;      ///< terrain.frequency (cycles per metre)
  double chunk_size = 32;       ///< terrain.chunk_size (m)
  double vertex_spacing = 0.5;  ///< terrain.vertex_spacing (m)
};

/// Trail (`[trail]`).
struct TrailConfig {
  bool enabled = true;         ///< trail.enabled
  double width = 1.5;          ///< trail.width (m)
  int control_points = 25;     ///< trail.control_points
  double control_spacing = 20; ///< trail.control_spacing (m)
  std::string surface = "random";  ///< trail.surface: a core/trail_surface.hpp name or "random"
};

/// World extent and streaming (`[world]`).
struct WorldConfig {
  double extent = 512;           ///< world.extent: side of the capture square (m)
  double render_distance = 250;  ///< world.render_distance (m)
};

/// Renderer switches (`[render]`).
struct RenderConfig {
  bool lod = true;  ///< render.lod
  double ground_cover_distance = 40;  ///< render.ground_cover_distance (m)
};

/// The LiDAR sensor (`[lidar]`): its model and where it rides on the capture camera.
struct LidarConfig {
  std::string preset = "vlp16";                     ///< lidar.preset: a [lidar.presets.<name>]
  std::vector<double> mount_offset = {0, 0, 0.3};   ///< lidar.mount_offset: metres forward, left, up of the camera
  std::vector<double> mount_rpy_deg = {0, 0, 0};    ///< lidar.mount_rpy_deg: roll, pitch, yaw from the camera's heading
  bool motion_distortion = false;                   ///< lidar.motion_distortion: autopilot sweeps move along the trail
};

/// The continuous `trajectory` sequence and its IMU (`[trajectory]`).
struct TrajectoryConfig {
  double speed = 1.4;               ///< trajectory.speed (m/s along the trail)
  double duration_s = 60;           ///< trajectory.duration_s (seconds)
  double start_m = 0;               ///< trajectory.start_m (arc length along the trail where it starts, m)
  double camera_hz = 10;            ///< trajectory.camera_hz (frames per second)
  double imu_hz = 200;              ///< trajectory.imu_hz (IMU samples per second)
  double bob_m = 0.02;              ///< trajectory.bob_m (height bob of the walk, amplitude, m)
  double sway_deg = 1.0;            ///< trajectory.sway_deg (roll sway of the walk, amplitude, degrees)
  double step_hz = 1.8;             ///< trajectory.step_hz (steps per second: the bob's frequency; sway at half)
  std::string imu_noise = "adis16448";  ///< trajectory.imu_noise: "adis16448" (EuRoC's IMU) or "none"
  bool flow = false;                ///< trajectory.flow: optical flow between consecutive frames
  std::string file;                 ///< trajectory.file: a TUM trajectory the walk follows ("" = the trail)
};

/// [rig]: the sensor rig of every capture; rig.preset fills the keys a config leaves out (core/rig_presets.hpp).
struct RigConfig {
  std::string preset = "mono";  ///< rig.preset: a RigPreset name (mono, stereo, ground_robot, drone)
  int cameras = 1;              ///< rig.cameras: 1, or 2 for a rectified stereo pair
  double baseline_m = 0.12;     ///< rig.baseline_m: stereo baseline, metres (the right camera along the left's +x)
  double height_m = 0;          ///< rig.height_m: ground camera height above the terrain, metres (0: camera.ground_height)
  double pitch_deg = 0;         ///< rig.pitch_deg: ground camera tilt from level, degrees (negative: down)
  bool lidar = false;           ///< rig.lidar: the rig carries a LiDAR (adds output type lidar)
};

/// Every config key, resolved (defaults = thesis defaults).
struct Config {
  int64_t seed = 0;          ///< seed (0..9 999 999 999); drawn from the clock when absent
  OutputConfig output;       ///< [output]
  LightingConfig lighting;   ///< [lighting]
  CapturesConfig captures;   ///< [captures]
  CameraConfig camera;       ///< [camera]
  VegetationConfig vegetation;  ///< [vegetation]
  TerrainConfig terrain;     ///< [terrain]
  TrailConfig trail;         ///< [trail]
  WorldConfig world;         ///< [world]
  RenderConfig render;       ///< [render]
  LidarConfig lidar;         ///< [lidar]
  TrajectoryConfig trajectory;  ///< [trajectory]
  RigConfig rig;             ///< [rig]
};

}  // namespace silva
