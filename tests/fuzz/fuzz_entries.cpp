#include "fuzz_entries.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <toml++/toml.h>

#include "pipeline/config/config_checks.hpp"
#include "pipeline/config/config_loader.hpp"
#include "pipeline/config/lighting_config.hpp"
#include "assets/import_mesh.hpp"
#include "assets/manifest.hpp"
#include "core/error.hpp"
#include "core/png_check.hpp"
#include "io/camera_json.hpp"
#include "io/ontology_file.hpp"
#include "io/pose_file.hpp"
#include "io/run_folder.hpp"

namespace silva::fuzz {

namespace {

namespace fs = std::filesystem;

/// A scratch folder of this process for readers that take a path.
const fs::path& scratch() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / ("silva-fuzz-" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

/// Writes `input` to `name` in the scratch folder; returns its path.
fs::path scratch_file(const std::string& name, std::string_view input) {
  const fs::path path = scratch() / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(input.data(), std::streamsize(input.size()));
  return path;
}

void config_file(std::string_view input) {
  const pipeline::LoadedConfig loaded = pipeline::parse_config_text(input, "fuzz.toml");
  pipeline::check_config(loaded);
}

void set_override(std::string_view input) {
  pipeline::LoadedConfig loaded;
  pipeline::apply_override(loaded, input);
  pipeline::check_config(loaded);
}

void pose_json(std::string_view input) { io::parse_pose_json(std::string(input), "fuzz.json"); }

void pose_csv(std::string_view input) { io::parse_pose_csv(std::string(input), "fuzz.csv"); }

void ontology(std::string_view input) { io::parse_ontology(std::string(input), "ontology.json"); }

void lighting(std::string_view input) {
  toml::table table;
  try {
    table = toml::parse(input, std::string_view("lighting.toml"));
  } catch (const toml::parse_error& e) {
    throw InputError(std::string("lighting.toml: invalid TOML: ") + std::string(e.description()));
  }
  pipeline::parse_lighting_presets(table, "lighting.toml");
  pipeline::parse_lighting_weathers(table, "lighting.toml");
}

void library(std::string_view input) { assets::parse_manifest(std::string(input), "library.json"); }

/// Imports `input` as an asset file named `name` whose materials "m" and assimp's default are classes.
void import_asset(const std::string& name, std::string_view input) {
  const std::map<std::string, Role> parts = {{"m", Role::Obstacle}, {"DefaultMaterial", Role::Obstacle}};
  assets::import_asset_lods(scratch_file(name, input), parts, false, "fuzz");
}

void gltf(std::string_view input) { import_asset("fuzz.gltf", input); }

void glb(std::string_view input) { import_asset("fuzz.glb", input); }

void obj(std::string_view input) { import_asset("fuzz.obj", input); }

void marker(std::string_view input) {
  scratch_file(".silva-run.json", input);
  io::read_run_marker(scratch());
}

void camera_json(std::string_view input) { io::parse_camera_json(std::string(input), "camera.json"); }

void png(std::string_view input) {
  check_png({reinterpret_cast<const uint8_t*>(input.data()), input.size()}, "label.png");
}

constexpr FuzzTarget kTargets[] = {
    {"config", config_file}, {"set", set_override}, {"pose_json", pose_json}, {"pose_csv", pose_csv},
    {"ontology", ontology},  {"lighting", lighting}, {"library", library},     {"gltf", gltf},
    {"glb", glb},            {"obj", obj},           {"marker", marker},  {"camera_json", camera_json},
    {"png", png},
};

}  // namespace

std::span<const FuzzTarget> fuzz_targets() { return kTargets; }

bool run_fuzz_input(const FuzzTarget& target, std::string_view input) {
  try {
    target.run(input);
    return true;
  } catch (const InputError&) {
    return false;
  } catch (const IoError&) {
    return false;
  }
}

}  // namespace silva::fuzz
