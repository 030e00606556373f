#include "fuzz_entries.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <string_view>

#include <toml++/toml.h>

#include "pipeline/config/config_checks.hpp"
#include "pipeline/config/config_loader.hpp"
#include "pipeline/config/lighting_config.hpp"
#include "assets/import_mesh.hpp"
#include "assets/manifest.hpp"
#include "core/error.hpp"
#include "core/ontology.hpp"
#include "assets/mesh_pack.hpp"
#include "core/png_check.hpp"
#include "io/camera_json.hpp"
#include "io/dataset_reader.hpp"
#include "io/ontology_file.hpp"
#include "io/pose_file.hpp"
#include "io/run_folder.hpp"
#include "io/trajectory_files.hpp"
#include "io/tum_trajectory_file.hpp"

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

/// Writes `input` to `path`, replacing it.
void write_file(const fs::path& path, std::string_view input) {
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(input.data(), std::streamsize(input.size()));
}

/// Writes `input` to `name` in the scratch folder; returns its path.
fs::path scratch_file(const std::string& name, std::string_view input) {
  const fs::path path = scratch() / name;
  write_file(path, input);
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

/// A finished dataset folder of two 16x12 "random" frames (marker, ontology, camera files) whose
/// manifest.json is `manifest`; made once per process, the manifest rewritten on every call.
const fs::path& dataset_folder(std::string_view manifest) {
  static const fs::path dir = [] {
    const fs::path run = io::prepare_run_folder(scratch() / "dataset", 1, "fuzz", io::FolderMode::Overwrite);
    std::ofstream(run / "ontology.json") << io::ontology_json(default_ontology());
    fs::create_directories(run / "random" / "camera");
    fs::create_directories(run / "random" / "semantic");
    fs::create_directories(run / "random" / "instance");
    for (const char* f : {"000000.json", "000001.json"}) std::ofstream(run / "random" / "camera" / f) << "{}";
    return run;
  }();
  write_file(dir / "manifest.json", manifest);
  return dir;
}

/// The manifest of a 16x12 dataset with two random frames of semantic and instance labels.
constexpr std::string_view kLabelManifest =
    R"({"seed": 1, "frames": {"random": 2}, "config": {"output": {"resolution": "16x12", "types": ["semantic",)"
    R"( "instance"]}, "captures": {"sequences": ["random"]}}})";

/// A damaged manifest.json of a dataset folder.
void dataset_manifest(std::string_view input) { io::open_dataset(dataset_folder(input)); }

/// A label PNG as frame 0's semantic image (8-bit class ids) and, when refused as that, as its instance image
/// (16-bit indices).
void label_png(std::string_view input) {
  const io::Dataset d = io::open_dataset(dataset_folder(kLabelManifest));
  write_file(d.file(d.frames[0], "semantic", "png"), input);
  write_file(d.file(d.frames[0], "instance", "png"), input);
  try {
    d.image(d.frames[0], "semantic", CV_8UC1);
  } catch (const InputError&) {
    d.image(d.frames[0], "instance", CV_16UC1);
  }
}

/// A trajectory sequence's imu.csv.
void imu_csv(std::string_view input) { io::read_euroc_imu_csv(scratch_file("imu.csv", input)); }

/// A trajectory sequence's imu.yaml.
void imu_yaml(std::string_view input) { io::read_kalibr_imu_yaml(scratch_file("imu.yaml", input)); }

/// A mesh cache entry (assets/mesh_pack.hpp): a pack of meshes, every mask hash found, and the
/// same bytes as a mask pack; refused when neither reads.
void mesh_pack(std::string_view input) {
  static const auto mask = std::make_shared<const AlphaMask>(AlphaMask{2, 2, {0, 255, 128, 254}, 0.5f, 0.0f});
  const auto lods = assets::unpack_lods(input, [](uint64_t) { return mask; });
  const auto alone = assets::unpack_mask(input);
  if (!lods && !alone) throw InputError("mesh pack: refused");
}

/// A user's TUM trajectory (trajectory.file).
void trajectory_file(std::string_view input) { io::read_tum_trajectory(scratch_file("walk.txt", input)); }

constexpr FuzzTarget kTargets[] = {
    {"config", config_file}, {"set", set_override}, {"pose_json", pose_json}, {"pose_csv", pose_csv},
    {"ontology", ontology},  {"lighting", lighting}, {"library", library},     {"gltf", gltf},
    {"glb", glb},            {"obj", obj},           {"marker", marker},  {"camera_json", camera_json},
    {"png", png},            {"manifest", dataset_manifest}, {"label_png", label_png},
    {"imu_csv", imu_csv},    {"imu_yaml", imu_yaml},     {"trajectory_file", trajectory_file},
    {"mesh_pack", mesh_pack},
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
