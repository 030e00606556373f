// `silva world`: check every input, then build (and optionally export) a world.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <memory>

#include "app/cli/command_options.hpp"
#include "app/cli/output_check.hpp"
#include "app/cli/subcommands.hpp"
#include "app/commands/world/world_command.hpp"
#include "pipeline/config/cost_estimate.hpp"
#include "pipeline/config/number_format.hpp"
#include "core/error.hpp"
#include "core/input_limits.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

namespace {

struct WorldArgs {
  ConfigSources sources;
  int threads = 0;
  std::optional<std::string> center;
  std::optional<double> radius;
  std::string export_path;
  std::string map_path;
  bool instancing = false;
  bool stats = false;
  bool force = false;
  OutputFlags output;
};

/// Parses a finite number that is all of `text`.
bool parse_double(std::string_view text, double& out) {
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, out);
  return !text.empty() && result.ec == std::errc{} && result.ptr == end && std::isfinite(out);
}

/// Parses "x,y" (metres).
WorldRequest::Disc parse_center(const std::string& text, double radius) {
  WorldRequest::Disc disc;
  if (!(radius > 0 && radius <= limits::kMaxPoseCoordinate))
    throw InputError("--radius " + format_number(radius) + ": must be more than 0 and at most " +
                     format_number(limits::kMaxPoseCoordinate) + " metres");
  disc.radius = radius;
  const size_t comma = text.find(',');
  const std::string_view view = text;
  if (comma == std::string::npos || !parse_double(view.substr(0, comma), disc.x) ||
      !parse_double(view.substr(comma + 1), disc.y) ||
      std::max(std::abs(disc.x), std::abs(disc.y)) > limits::kMaxPoseCoordinate) {
    throw InputError("--center " + text + ": expected x,y in metres (|x|, |y| <= " +
                     format_number(limits::kMaxPoseCoordinate) + "), e.g. --center=-40.5,12");
  }
  return disc;
}

/// True when `path` ends in `ext` (e.g. ".glb", any case).
bool has_extension(const std::filesystem::path& path, const std::string& ext) {
  std::string e = path.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e == ext;
}

/// Throws IoError unless the folder that will hold `path` is writable.
void check_parent_writable(const std::filesystem::path& path) {
  const std::filesystem::path parent = path.parent_path();
  check_writable_dir(parent.empty() ? std::filesystem::path(".") : parent);
}

int world(const WorldArgs& args) {
  const Reporter reporter(args.output);
  WorldRequest request;
  request.config = load_run_config(args.sources, reporter, /*draw_seed=*/true);
  if (args.center) request.region = parse_center(*args.center, *args.radius);
  check_cost(estimate_world_cost(request.config.config, args.radius), args.force, "world");
  if (!args.export_path.empty()) {
    request.export_path = args.export_path;
    if (!has_extension(request.export_path, ".glb")) {
      throw InputError("--export " + args.export_path + ": the export is binary glTF, name it FILE.glb");
    }
    check_parent_writable(request.export_path);
  }
  if (!args.map_path.empty()) {
    request.map_path = args.map_path;
    if (!has_extension(request.map_path, ".png")) {
      throw InputError("--map " + args.map_path + ": the class map is a PNG image, name it FILE.png");
    }
    check_parent_writable(request.map_path);
  }
  request.instancing = args.instancing;
  request.stats = args.stats;
  request.threads = resolved_threads(args.threads);
  const ThreadLimit limit(args.threads);
  return run_world(request, reporter);
}

}  // namespace

Handler add_world_command(CLI::App& root) {
  auto args = std::make_shared<WorldArgs>();
  CLI::App* cmd = root.add_subcommand(
      "world",
      "Build a world without capturing: by default every chunk within world.render_distance of "
      "the capture region, or the chunks intersecting a disc (--center, --radius). Optionally "
      "export it as binary glTF and print statistics.");
  add_config_options(*cmd, args->sources, /*with_seed=*/true);
  add_threads_option(*cmd, args->threads);
  CLI::Option* center = cmd->add_option_function<std::string>(
      "--center", [args](const std::string& c) { args->center = c; },
      "centre x,y of the disc to build, metres (write --center=-10,5 for a negative x)")
      ->type_name("X,Y");
  CLI::Option* radius = cmd->add_option_function<double>(
      "--radius", [args](double r) { args->radius = r; }, "radius of the disc to build, metres")
      ->type_name("R");
  center->needs(radius);
  radius->needs(center);
  CLI::Option* exported = cmd->add_option("--export", args->export_path,
                                          "write the world as binary glTF 2.0 (Z-up world under a Y-up root)")
      ->type_name("FILE.glb");
  cmd->add_flag("--instancing", args->instancing,
                "export repeated meshes with EXT_mesh_gpu_instancing (very large worlds)")
      ->needs(exported);
  cmd->add_option("--map", args->map_path,
                  "write a top-down class map of the world (0.5 m per pixel, ontology colours)")
      ->type_name("FILE.png");
  cmd->add_flag("--stats", args->stats, "print chunk, object and triangle counts and timings");
  cmd->add_flag("--force", args->force, "build even when the estimate exceeds this machine's memory");
  add_output_flags(*cmd, args->output);
  cmd->footer(
      "Examples:\n"
      "  silva world --seed 7 --stats\n"
      "  silva world --seed 7 --center 0,0 --radius 64 --export world.glb\n"
      "  silva world --seed 7 --map world.png\n"
      "  silva world --config configs/demo.toml --export big.glb --instancing --json");
  return [args] { return world(*args); };
}

}  // namespace silva::app
