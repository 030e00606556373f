// `silva verify DIR`: rebuilds the world of a finished dataset from its run marker and manifest (same
// config, seed and asset library), casts rays through pixel centres of a seeded choice of frames with
// the Embree ray caster (raycast/, independent of the rasteriser) and compares the hits with the label,
// depth, normal and LiDAR files; writes verify.json and VERIFY.md into the dataset.
#include <algorithm>
#include <cmath>

#include "pipeline/console/progress.hpp"
#include "pipeline/console/version.hpp"
#include "app/commands/verify/verify_command.hpp"
#include "app/commands/verify/verify_drawn_scene.hpp"
#include "app/commands/verify/verify_report.hpp"
#include "pipeline/config/config_checks.hpp"
#include "pipeline/config/config_print.hpp"
#include "pipeline/config/run_setup.hpp"
#include "pipeline/schedule/world_schedule.hpp"
#include "core/error.hpp"
#include "core/rng.hpp"
#include "core/stopwatch.hpp"
#include "io/atomic_file.hpp"
#include "io/capture_set.hpp"
#include "io/lidar_files.hpp"
#include "io/run_folder.hpp"
#include "io/sha256.hpp"
#include "raycast/camera_rays.hpp"
#include "systems/aim_camera.hpp"
#include "systems/cast_lidar.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

namespace fs = std::filesystem;

namespace {

/// Chunks the verifier's cache keeps between frames (autopilot neighbours share most of theirs).
constexpr size_t kCacheChunks = 256;

/// The run's config: the marker's TOML (what --resume reloads), which must be the manifest's config.
LoadedConfig dataset_config(const io::Dataset& d) {
  const fs::path marker_path = d.dir / ".silva-run.json";
  const std::optional<io::RunMarker> marker = io::read_run_marker(d.dir);
  if (!marker || marker->config.empty())
    throw InputError(marker_path.string() + ": records no config; verify needs a dataset written by this Silva");
  LoadedConfig loaded = parse_config_text(marker->config, marker_path.string());
  loaded.config.seed = d.seed;
  loaded.seed_given = true;
  loaded.config.output.dir = fs::absolute(d.dir).parent_path().string();
  check_config(loaded);
  nlohmann::json config = config_to_json(loaded);
  config["output"].erase("dir");
  config["output"].erase("formats");
  if (config != d.manifest.at("config"))
    throw InputError((d.dir / "manifest.json").string() + ": its config is not the run marker's (" +
                     marker_path.string() + "); the dataset was edited or mixed from two runs");
  return loaded;
}

/// InputError unless the manifest names this version of Silva (another version may build another world).
void check_version(const io::Dataset& d) {
  const nlohmann::json& v = d.manifest.contains("silva_version") ? d.manifest["silva_version"] : nlohmann::json();
  const std::string version = v.is_string() ? v.get<std::string>() : v.dump();
  if (version != silva_version())
    throw InputError((d.dir / "manifest.json").string() + ": written by Silva " + version + ", this is Silva " +
                     silva_version() + "; only the version that wrote a dataset rebuilds its world");
}

/// InputError unless the dataset was made with the asset library this process loads.
void check_library(const io::Dataset& d, const RunSetup& setup) {
  const std::string library = io::sha256_file(setup.library_json);
  const nlohmann::json& sha = d.manifest.contains("sha256") ? d.manifest["sha256"] : nlohmann::json();
  if (!sha.is_object() || sha.value("asset_library", "") != library)
    throw InputError((d.dir / "manifest.json").string() + ": made with another asset library than " +
                     setup.library_json.string() + " (sha256 differs); set SILVA_ASSETS to the library it was made with");
}

/// The frames to check, in global order: `n` strata of the global frame list, one seeded frame from each
/// (every frame when the dataset has no more than `n`).
std::vector<size_t> choose_frames(const io::Dataset& d, int n) {
  const size_t total = d.frames.size(), want = std::min(total, size_t(n));
  std::vector<size_t> chosen;
  Rng rng(uint64_t(d.seed), 0, Purpose::VerifySample);
  for (size_t k = 0; k < want; ++k) {
    const size_t first = k * total / want, last = (k + 1) * total / want;
    chosen.push_back(first + rng.below(uint32_t(last - first)));
  }
  return chosen;
}

/// Pixels of frame `global` to cast, in 4x4 block order: all, or each with probability `sample`
/// (seeded by the dataset's seed, the frame's global index and the pixel).
std::vector<uint32_t> sample_pixels(int width, int height, double sample, int64_t seed, int global) {
  std::vector<uint32_t> pixels = raycast::block_order(width, height);
  if (sample >= 1.0) return pixels;
  const double limit = sample * 18446744073709551616.0;
  std::erase_if(pixels, [&](uint32_t p) {
    return double(rng_bits(uint64_t(seed), uint64_t(global), uint64_t(Purpose::VerifySample), p)) >= limit;
  });
  return pixels;
}

/// The files a checked frame needs, of its left (or only) camera or with `right` of a stereo rig's right camera
/// (InputError naming the first that is missing).
void check_frame_files(const io::Dataset& d, const io::DatasetFrame& f, bool right) {
  const auto file = [&](const char* folder, const char* ext) { return d.file(f, io::camera_folder(folder, right), ext); };
  std::vector<fs::path> need = {file("camera", "json"), file("semantic", "png")};
  need.push_back(d.has("depth_exr") ? file("depth_exr", "exr") : file("depth", "png"));
  if (d.has("instance")) need.push_back(file("instance", "png")), need.push_back(file("instance", "json"));
  if (d.has("normal")) need.push_back(file("normal", "png"));
  if (d.has("lidar") && !right) need.push_back(file("lidar", "bin")), need.push_back(file("lidar_labels", "label"));
  std::error_code ec;
  for (const fs::path& p : need)
    if (!fs::is_regular_file(p, ec)) throw InputError(p.string() + ": missing from the dataset (verify reads it)");
}

/// The frame's label, depth and normal files of one camera (`right`: a stereo rig's right camera).
FrameTruth read_truth(const io::Dataset& d, const io::DatasetFrame& f, const Camera& camera, bool right) {
  const auto folder = [right](const char* name) { return io::camera_folder(name, right); };
  FrameTruth t;
  const cv::Mat semantic = d.image(f, folder("semantic"), CV_8UC1);
  if (semantic.cols != camera.width || semantic.rows != camera.height)
    throw InputError(d.file(f, folder("semantic"), "png").string() + ": not the size its camera file gives");
  t.width = semantic.cols;
  t.height = semantic.rows;
  const size_t n = size_t(t.width) * size_t(t.height);
  t.semantic.assign(semantic.datastart, semantic.datastart + n);
  if (d.has("depth_exr")) {
    const cv::Mat depth = io::read_depth_exr(d.file(f, folder("depth_exr"), "exr"), semantic);
    t.depth.assign(depth.ptr<float>(), depth.ptr<float>() + n);
  } else {
    const cv::Mat depth = d.image(f, folder("depth"), CV_16UC1);
    t.depth.resize(n);
    for (size_t i = 0; i < n; ++i) t.depth[i] = float(depth.ptr<uint16_t>()[i]) / 1000.0f;
    t.depth_step = 0.001;
  }
  if (d.has("instance")) {
    const fs::path table_path = d.file(f, folder("instance"), "json");
    const std::vector<io::InstanceEntry> table = io::read_instance_table(table_path);
    const cv::Mat index = d.image(f, folder("instance"), CV_16UC1);
    t.instance.resize(n);
    for (size_t i = 0; i < n; ++i) {
      const uint16_t k = index.ptr<uint16_t>()[i];
      if (k > table.size())
        throw InputError(d.file(f, folder("instance"), "png").string() + ": index " + std::to_string(k) + " is not in " +
                         table_path.string());
      t.instance[i] = k ? table[k - 1].instance_id : 0;
    }
  }
  if (d.has("normal")) {
    const cv::Mat normal = d.image(f, folder("normal"), CV_8UC3);
    t.normal.resize(n);
    for (size_t i = 0; i < n; ++i) {
      const uint8_t* bgr = normal.ptr<uint8_t>() + 3 * i;
      if (bgr[0] || bgr[1] || bgr[2])
        t.normal[i] = Vec3f(float(bgr[2]), float(bgr[1]), float(bgr[0])) / 127.5f - Vec3f::Ones();
    }
  }
  return t;
}

/// The LiDAR-to-camera transform the manifest records (sensors.lidar.lidar_to_camera, 4x4 row-major).
Mat4d manifest_lidar_to_camera(const io::Dataset& d) {
  Mat4d m;
  try {
    const nlohmann::json& rows = d.manifest.at("sensors").at("lidar").at("lidar_to_camera");
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) m(r, c) = rows.at(size_t(r)).at(size_t(c)).get<double>();
  } catch (const nlohmann::json::exception& e) {
    throw InputError((d.dir / "manifest.json").string() + ": sensors.lidar.lidar_to_camera is missing or not 4x4 (" +
                     e.what() + ")");
  }
  return m;
}

/// The frame's LiDAR scan and labels compared with its files (InputError when they do not match up).
LidarTally check_lidar_frame(const io::Dataset& d, const io::DatasetFrame& f, const FrameTruth& truth,
                             const Camera& camera, const Mat4d& lidar_to_camera) {
  const std::vector<Vec3f> points = io::read_kitti_scan(d.file(f, "lidar", "bin"));
  const std::vector<uint32_t> labels = io::read_semantic_kitti_labels(d.file(f, "lidar_labels", "label"));
  if (labels.size() != points.size())
    throw InputError(d.file(f, "lidar_labels", "label").string() + ": " + std::to_string(labels.size()) +
                     " labels for " + std::to_string(points.size()) + " points");
  return compare_lidar(truth, camera, lidar_to_camera, points, labels);
}

/// Writes verify.json and VERIFY.md into the dataset and reports the verdict of `frames` checked frames; the exit
/// code: 0 on a pass, kExitVerifyFailed otherwise.
int write_verdict(const io::Dataset& d, const VerifyRequest& request, const VerifyCounts& counts, size_t frames,
                  double seconds, const Reporter& reporter) {
  const nlohmann::json verify = verify_json(d, request, counts);
  io::write_file_atomic(d.dir / "verify.json", verify.dump(2) + "\n");
  io::write_file_atomic(d.dir / "VERIFY.md", verify_markdown(verify));
  const bool pass = verify["verdict"]["pass"].get<bool>();
  char line[256];
  std::snprintf(line, sizeof line, "%s: class %.4f %% of interior pixels, depth within %.3g %% on %.4f %% of hit pixels",
                pass ? "PASS" : "FAIL", 100 * verify["class"]["interior"]["agreement"].get<double>(),
                request.depth_tolerance, 100 * verify["depth"]["within_tolerance"].get<double>());
  nlohmann::json summary = verify;
  summary["ok"] = pass;
  summary["exit_code"] = pass ? 0 : kExitVerifyFailed;
  summary["run_dir"] = d.dir.string();
  summary["seconds"] = seconds;
  reporter.result(summary, std::string("silva verify: ") + line + " (" + std::to_string(frames) +
                               " frames); wrote " + (d.dir / "VERIFY.md").string() + " and verify.json");
  return pass ? 0 : kExitVerifyFailed;
}

}  // namespace

int run_verify(const VerifyRequest& request, const Reporter& reporter) {
  const Stopwatch clock;
  const io::Dataset d = io::open_dataset(request.run_dir);
  check_version(d);
  d.require("semantic", "verify");
  if (!d.has("depth_exr")) d.require("depth", "verify");
  if (d.frames.empty()) throw InputError(d.dir.string() + ": the dataset holds no frames");
  const std::vector<size_t> chosen = choose_frames(d, request.frames);
  const bool stereo = io::manifest_stereo(d.manifest);
  for (const size_t i : chosen) {
    check_frame_files(d, d.frames[i], false);
    if (stereo) check_frame_files(d, d.frames[i], true);
  }
  const LoadedConfig loaded = dataset_config(d);
  const RunSetup setup = make_run_setup(loaded);
  check_library(d, setup);
  const Mat4d lidar_to_camera = d.has("lidar") ? manifest_lidar_to_camera(d) : Mat4d::Identity();
  const double lidar_reach = d.has("lidar") ? setup.lidar.max_range : 0.0;
  reporter.note("silva verify: " + std::to_string(chosen.size()) + " of " + std::to_string(d.frames.size()) +
                " frames" + (stereo ? " (both cameras of the stereo pair)" : "") + ", " +
                std::to_string(int(std::lround(100 * request.sample))) + " % of their pixels");

  pipeline::WorldSchedule schedule(setup.world, kCacheChunks);  // streams the chunks each frame casts against
  const bool as_drawn = loaded.config.render.lod && !request.full_detail;
  const double ground_cover = loaded.config.render.ground_cover_distance;
  systems::ChunkRayScene rays;  // full detail: groups per chunk, kept while frames share chunks
  DrawnRayScene drawn;          // as drawn: each frame's instances at their LOD
  const systems::SceneBuilder builder(*setup.library);
  CompareOptions options;
  options.depth_tolerance = request.depth_tolerance / 100.0;
  VerifyCounts counts;
  counts.depth_source = d.has("depth_exr") ? "depth_exr" : "depth";
  counts.instances = d.has("instance");
  counts.normals = d.has("normal");
  if (d.has("lidar")) counts.lidar = LidarTally{};
  std::vector<raycast::RayHit> hits;  // kept across frames: a frame's hits are tens of MB
  Progress progress(reporter, int(chosen.size()), "frames");
  // One camera of a chosen frame: its pixels cast against the world and compared with its files.
  const auto check_view = [&](const io::DatasetFrame& f, bool right) {
    const Camera camera = io::read_camera_json(d.file(f, io::camera_folder("camera", right), "json")).camera;
    const FrameTruth truth = read_truth(d, f, camera, right);
    const auto chunks = schedule.chunks(systems::capture_chunks(camera, setup.world.chunk_size(), lidar_reach));
    if (as_drawn)
      drawn.show(builder.build(chunks, camera.position(), ground_cover), camera);
    else
      rays.sync(chunks, builder, ground_cover, camera.position());
    const std::vector<uint32_t> pixels = sample_pixels(camera.width, camera.height, request.sample, d.seed, f.global_index);
    hits.resize(pixels.size());
    raycast::cast_pixels(as_drawn ? drawn.scene() : *rays.scene, camera, pixels, hits, /*exact_masks=*/true);
    const VerifyTally tally = compare_frame(truth, pixels, hits, d.ontology, options);
    counts.pixels.merge(tally);
    nlohmann::json frame = tally_summary(tally, counts.instances);
    frame["sequence"] = f.sequence;
    frame["frame"] = f.frame;
    if (stereo) frame["camera"] = right ? "right" : "left";
    if (counts.lidar && !right) {
      const LidarTally lidar = check_lidar_frame(d, f, truth, camera, lidar_to_camera);
      counts.lidar->merge(lidar);
      frame["lidar_class_agreement"] = lidar.compared ? double(lidar.class_agree) / double(lidar.compared) : 1.0;
    }
    counts.frames.push_back(frame);
  };
  for (size_t k = 0; k < chosen.size(); ++k) {
    check_view(d.frames[chosen[k]], false);
    if (stereo) check_view(d.frames[chosen[k]], true);
    progress.update(int(k + 1));
  }
  progress.finish();

  return write_verdict(d, request, counts, chosen.size(), clock.seconds(), reporter);
}

}  // namespace silva::app
