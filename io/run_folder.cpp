#include "io/run_folder.hpp"

#include <cstdio>
#include <nlohmann/json.hpp>
#include <system_error>
#include <vector>

#include "core/error.hpp"
#include "core/input_limits.hpp"
#include "io/atomic_file.hpp"

namespace silva::io {

namespace fs = std::filesystem;

namespace {
constexpr const char* kMarker = ".silva-run.json";

/// True when `dir` holds nothing but (maybe) leftover temp files: a run killed while it wrote
/// its marker left no run yet.
bool holds_no_run(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return false;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    const bool temp = name.size() > kTempSuffix.size() && name.ends_with(kTempSuffix);
    if (!temp || entry.is_directory(ec)) return false;
  }
  return !ec;
}

void create_dirs(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw IoError("cannot create output folder " + dir.string() + ": " + ec.message());
}

void empty_dir(const fs::path& dir) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    fs::remove_all(entry.path(), ec);
    if (ec) throw IoError("cannot remove " + entry.path().string() + ": " + ec.message());
  }
  if (ec) throw IoError("cannot list " + dir.string() + ": " + ec.message());
}

void write_marker(const fs::path& run_dir, int64_t seed, const std::string& config_hash,
                  const std::string& config_text) {
  nlohmann::json j = {{"seed", seed}, {"config_hash", config_hash}};
  if (!config_text.empty()) j["config"] = config_text;
  write_file_atomic(run_dir / kMarker, j.dump(2) + "\n");
}
}  // namespace

std::string seed_folder_name(int64_t seed) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%010lld", static_cast<long long>(seed));
  return buf;
}

std::optional<RunMarker> read_run_marker(const fs::path& run_dir) {
  const fs::path path = run_dir / kMarker;
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(path, ec))) return std::nullopt;
  try {
    const std::string text = limits::read_input_file(path, "run marker");
    limits::check_json_depth(text, path.string());
    const nlohmann::json j = nlohmann::json::parse(text);
    return RunMarker{j.at("seed").get<int64_t>(), j.at("config_hash").get<std::string>(),
                     j.value("config", std::string())};
  } catch (const std::exception& e) {
    throw InputError(path.string() + ": corrupt run marker (" + e.what() +
                     "); remove the folder or use --overwrite");
  }
}

int64_t find_resumable_seed(const fs::path& output_dir) {
  std::vector<int64_t> seeds;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(output_dir, ec))
    if (auto marker = read_run_marker(entry.path())) seeds.push_back(marker->seed);
  if (seeds.size() == 1) return seeds[0];
  if (seeds.empty())
    throw InputError("--resume: no run folder with a .silva-run.json marker under " + output_dir.string() +
                     "; pass --seed N");
  std::string list;
  for (int64_t s : seeds) list += (list.empty() ? "" : ", ") + seed_folder_name(s);
  throw InputError("--resume: several runs under " + output_dir.string() + " (" + list + "); pass --seed N");
}

fs::path prepare_run_folder(const fs::path& output_dir, int64_t seed, const std::string& config_hash,
                            FolderMode mode, const std::string& config_text) {
  fs::path run_dir = output_dir / seed_folder_name(seed);
  std::error_code ec;
  if (mode == FolderMode::Overwrite && fs::is_symlink(run_dir, ec))
    throw InputError(run_dir.string() + " is a symbolic link; --overwrite empties only a real folder (remove the "
                     "link or pass the folder it points to as --out)");
  const bool exists = fs::exists(run_dir, ec);
  if (exists && !fs::is_directory(run_dir, ec))
    throw InputError("output path " + run_dir.string() + " exists and is not a folder");
  if (exists && holds_no_run(run_dir)) {
    // A shard leaves them: another shard may be writing its marker right now.
    if (mode != FolderMode::Shard) remove_temp_files(run_dir);
  } else if (exists && mode == FolderMode::Overwrite) {
    empty_dir(run_dir);  // whatever it holds, a corrupt marker included
  } else if (exists) {
    const auto marker = read_run_marker(run_dir);
    const bool same = marker && marker->config_hash == config_hash;
    if (!same) {
      throw InputError(run_dir.string() + " holds " +
                       (marker ? std::string("a run with a different config or input files (pose file, asset library)")
                               : std::string("files that are not a Silva run")) +
                       "; use --overwrite to replace it or choose another --out");
    } else if (mode == FolderMode::Fresh) {
      throw InputError(run_dir.string() + " already holds this run; use --resume to continue it or "
                       "--overwrite to start again");
    } else if (mode == FolderMode::Resume) {
      remove_temp_files(run_dir);
    }
  }
  create_dirs(run_dir);
  write_marker(run_dir, seed, config_hash, config_text);
  return run_dir;
}

}  // namespace silva::io
