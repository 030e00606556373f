#pragma once
/// @file What each subcommand asks of the pipeline, after the CLI has checked every input.
/// The run_* functions are the pipeline entry points (app/commands/run_*.cpp); `silva bench` and
/// `silva profile` call into the harness of bench/harness/.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/cli/reporter.hpp"
#include "app/config/config_loader.hpp"
#include "io/dataset_card.hpp"
#include "io/dataset_reader.hpp"
#include "io/export_formats.hpp"

namespace silva::app {

/// `--shard i/N`: this process renders the frames whose global index mod N = i.
struct Shard {
  int index = 0;  ///< i, 0 ≤ i < count
  int count = 1;  ///< N ≥ 1
};

/// `silva generate`: capture a dataset into <output.dir>/<seed>/.
struct GenerateRequest {
  LoadedConfig config;        ///< Checked; output.dir already holds --out. seed_given is false only
                              ///< for --resume without a seed (take it from the run marker).
  int threads = 1;            ///< Resolved thread count (for run.json).
  bool resume = false;        ///< --resume: continue the run in the folder.
  bool overwrite = false;     ///< --overwrite: empty <seed>/ first.
  std::optional<Shard> shard; ///< --shard i/N (seed is then explicit).
};

/// `silva world`: build the world (default or a disc), optionally export glTF, report stats.
struct WorldRequest {
  /// `--center x,y --radius R`: build the chunks intersecting this disc.
  struct Disc {
    double x = 0, y = 0, radius = 0;  ///< Centre (m) and radius (m, > 0).
  };
  LoadedConfig config;              ///< Checked, seed resolved.
  int threads = 1;                  ///< Resolved thread count.
  std::optional<Disc> region;       ///< nullopt: the default world (CONTRACT.md).
  std::filesystem::path export_path;  ///< --export FILE.glb ("" = no export).
  bool instancing = false;          ///< --instancing: EXT_mesh_gpu_instancing in the export.
  std::filesystem::path map_path;   ///< --map FILE.png: top-down class map ("" = none).
  bool stats = false;               ///< --stats: print counts and timings.
};

/// `silva assets build`: generate the procedural asset library.
struct AssetsBuildRequest {
  std::filesystem::path out_dir;  ///< --out DIR ("" = the library folder the pipeline uses by default).
  bool glb = false;               ///< --glb: write every variant's meshes as .glb files too.
  uint32_t max_variants = UINT32_MAX;  ///< --variants N: at most N variants per generator.
};

/// `silva assets sheet`: a contact sheet of built-in asset variants.
struct AssetsSheetRequest {
  std::string kind;               ///< Kind name or factory prefix (checked by the CLI).
  int count = 6;                  ///< Variants per factory (1..64).
  int cell = 320;                 ///< Side of one view in pixels (64..2048).
  int columns = 3;                ///< Variants per row (1..16).
  uint64_t seed = 0;              ///< Asset seed.
  std::filesystem::path out;      ///< PNG file to write.
};

/// `silva merge DIR`: check shards cover every frame, then write manifest.json.
struct MergeRequest {
  std::filesystem::path run_dir;  ///< <output.dir>/<seed>/, an existing folder.
};

/// `silva export DIR --format F...`: convert a finished dataset.
struct ExportRequest {
  std::filesystem::path run_dir;           ///< <output.dir>/<seed>/.
  std::vector<io::ExportFormat> formats;   ///< In the order given.
  bool all = false;                        ///< --format all: every camera format, semantickitti with lidar.
  std::filesystem::path out_dir;           ///< Each format goes to <out_dir>/<format>/.
  bool overwrite = false;                  ///< --overwrite: replace an existing <out_dir>/<format>/.
};

/// `silva verify DIR`: re-cast frames of a finished dataset with the ray caster and compare.
struct VerifyRequest {
  std::filesystem::path run_dir;    ///< <output.dir>/<seed>/.
  int frames = 8;                   ///< --frames N: frames checked (all when the dataset has fewer).
  double sample = 0.25;             ///< --sample F: share of each frame's pixels cast, in (0, 1].
  double min_class = 99.9;          ///< --min-class: % of interior pixels whose class must agree.
  double min_depth = 99.9;          ///< --min-depth: % of hit pixels whose depth must agree.
  double depth_tolerance = 0.1;     ///< --depth-tolerance: relative depth error (%) that still agrees.
  bool full_detail = false;         ///< --full-detail: cast full detail even where the dataset drew a coarser LOD.
};

/// Exit code of `silva verify` when the dataset does not meet the thresholds (CONTRACT.md).
inline constexpr int kExitVerifyFailed = 4;

/// `silva bench`: the end-to-end benchmark harness.
struct BenchRequest {
  bool quick = false;                 ///< --quick: a short subset.
  std::filesystem::path out_dir;      ///< --out DIR ("" = bench/results of the source tree).
};

/// `silva profile placement`: a density (x elevation x trail) sweep over seeds, profiled per class.
struct ProfilePlacementRequest {
  LoadedConfig config;              ///< Checked base config; its seed is the sweep's first seed.
  int threads = 1;                  ///< Resolved thread count.
  std::optional<double> radius;     ///< --radius R around the origin (nullopt = the default world).
  std::vector<double> densities;    ///< --densities: vegetation.density values (%), each 1..25.
  int seeds = 3;                    ///< --seeds N: seeds seed, seed+1, ..., seed+N-1.
  std::vector<double> elevations;   ///< --elevations: terrain.max_elevation values (m), each 0..50.
  std::vector<bool> trails;         ///< --trail on,off: trail.enabled values.
  std::filesystem::path out_dir;    ///< --out DIR: placement.json, placement.csv, heatmaps, charts.
};

/// `silva view`: a local web page exploring the world, with captures into the output folder.
struct ViewRequest {
  ConfigSources sources;           ///< --config, --set, --seed (checked by the session).
  std::string host = "127.0.0.1";  ///< --host: the address to listen on.
  int port = 8080;                 ///< --port (0 = any free port, printed).
};

/// Runs the generate pipeline; returns the exit code. Throws InputError / IoError.
int run_generate(const GenerateRequest& request, const Reporter& reporter);
/// Builds (and exports) a world; returns the exit code. Throws InputError / IoError.
int run_world(const WorldRequest& request, const Reporter& reporter);
/// Builds the asset library; returns the exit code. Throws InputError / IoError.
int run_assets_build(const AssetsBuildRequest& request, const Reporter& reporter);
/// Renders and writes an asset contact sheet; returns the exit code. Throws IoError.
int run_assets_sheet(const AssetsSheetRequest& request, const Reporter& reporter);
/// Merges shards of a run; returns the exit code. Throws InputError / IoError.
int run_merge(const MergeRequest& request, const Reporter& reporter);
/// Exports a finished dataset; returns the exit code. Throws InputError / IoError.
int run_export(const ExportRequest& request, const Reporter& reporter);
/// Writes `formats` of `dataset` into <out_dir>/<format>/ (each moved into place when complete) and returns
/// [{"format", "dir", "seconds"}, ...]. An existing non-empty target without `overwrite` is InputError,
/// checked for every format before any is written.
nlohmann::json export_formats(const io::Dataset& dataset, const std::vector<io::ExportFormat>& formats,
                              const std::filesystem::path& out_dir, bool overwrite);
class WorldSchedule;
struct RunSetup;

/// What a generate run hands the card so that it reads less back: the label counts of the frames it wrote,
/// and its world (schedule and setup) for the class map under the cameras. Empty: everything is read from
/// the dataset, and the world is rebuilt from the config its run marker records.
struct CardInputs {
  const io::KnownCounts* known = nullptr;  ///< Label counts of the frames this process wrote.
  WorldSchedule* schedule = nullptr;       ///< The run's schedule (its chunk cache).
  const RunSetup* setup = nullptr;         ///< The run's loaded inputs (library, ontology, world context).
};

/// Writes <run_dir>/CARD.md, card.json and card_*.png for a finished dataset (also at the end of generate
/// and merge). Throws InputError / IoError.
void write_card(const std::filesystem::path& run_dir, const CardInputs& inputs = {});
/// `silva card`: write_card and report; returns the exit code. Throws InputError / IoError.
int run_card(const std::filesystem::path& run_dir, const Reporter& reporter);
/// Verifies a finished dataset, writes DIR/verify.json and DIR/VERIFY.md; returns 0 when it meets the
/// thresholds, kExitVerifyFailed when not. Throws InputError / IoError.
int run_verify(const VerifyRequest& request, const Reporter& reporter);
/// Runs the benchmark harness; returns the exit code. Throws InputError / IoError.
int run_bench(const BenchRequest& request, const Reporter& reporter);
/// Serves the view until Ctrl-C (then throws Interrupted: exit 130). Throws InputError / IoError.
int run_view(const ViewRequest& request, const Reporter& reporter);
/// Profiles placement over a sweep; returns the exit code. Throws InputError / IoError.
int run_profile_placement(const ProfilePlacementRequest& request, const Reporter& reporter);

}  // namespace silva::app
