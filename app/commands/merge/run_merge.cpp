// `silva merge DIR`: checks that the shards of a run share one config and cover every frame,
// removes leftover temp files, then writes manifest.json (and a combined run.json).
#include <filesystem>
#include <map>
#include <regex>

#include "app/commands/card/card_command.hpp"
#include "app/commands/merge/merge_command.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/dataset_reader.hpp"
#include "io/capture_set.hpp"
#include "io/json_read.hpp"
#include "io/output_types.hpp"
#include "io/run_folder.hpp"
#include "io/run_lock.hpp"
#include "io/sequence_flow.hpp"

namespace silva::app {

namespace fs = std::filesystem;

namespace {
nlohmann::json read_json(const fs::path& path) {
  return io::parse_json_text(io::read_text_file(path), path.string());
}

int merge_shards(const MergeRequest& request, const Reporter& reporter) {
  const fs::path dir = request.run_dir;
  if (!io::read_run_marker(dir)) throw InputError(dir.string() + ": not a Silva run folder (no .silva-run.json)");
  const io::RunLock lock = io::lock_run_folder(dir, /*exclusive=*/true);  // no shard still writing
  const std::regex name_re(R"(run\.shard-(\d+)-of-(\d+)\.json)");
  std::map<int, nlohmann::json> shards;
  int count = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    std::smatch m;
    const std::string name = entry.path().filename().string();
    if (!std::regex_match(name, m, name_re)) continue;
    const int n = std::stoi(m[2]);
    if (count && n != count)
      throw InputError(dir.string() + ": shard files of different shard counts (" + std::to_string(count) + " and " +
                       std::to_string(n) + ")");
    count = n;
    shards[std::stoi(m[1])] = read_json(entry.path());
  }
  if (!count) throw InputError(dir.string() + ": no run.shard-i-of-N.json files; run silva generate --shard i/N first");
  for (int i = 0; i < count; ++i)
    if (!shards.count(i))
      throw InputError(dir.string() + ": shard " + std::to_string(i) + " of " + std::to_string(count) +
                       " has not finished (run.shard-" + std::to_string(i) + "-of-" + std::to_string(count) +
                       ".json missing)");
  const nlohmann::json& manifest = shards[0].at("manifest");
  for (const auto& [i, record] : shards)
    if (record.at("manifest") != manifest)
      throw InputError(dir.string() + ": shard " + std::to_string(i) + " was made with a different config than shard 0");
  const io::OutputSelection outputs =
      io::OutputSelection::from_names(manifest.at("config").at("output").at("types").get<std::vector<std::string>>());
  const bool stereo = io::manifest_stereo(manifest);
  int frames = 0;
  for (const auto& [sequence, n] : manifest.at("frames").items())
    for (int f = 0; f < n.get<int>(); ++f, ++frames) {
      std::vector<std::string> files = io::frame_file_names(outputs, f, stereo);
      files.push_back(io::frame_file("camera", f, "json"));
      for (const std::string& file : files)
        if (!fs::is_regular_file(dir / sequence / file))
          throw InputError(dir.string() + ": frame " + sequence + "/" + std::to_string(f) + " is missing " + file +
                           "; rerun its shard with the same arguments to complete it");
    }
  const size_t temps = io::remove_temp_files(dir);
  nlohmann::json run = {{"merged_shards", count}, {"frames", frames}, {"temp_files_removed", temps}};
  uint64_t bytes = 0;
  double wall = 0;
  for (const auto& [i, record] : shards) {
    bytes += record.value("bytes_written", uint64_t(0));
    wall = std::max(wall, record.at("timings_s").value("wall", 0.0));
  }
  run["bytes_written"] = bytes;
  run["slowest_shard_wall_s"] = wall;
  io::write_file_atomic(dir / "run.json", run.dump(2) + "\n");
  io::write_file_atomic(dir / "manifest.json", manifest.dump(2) + "\n");
  if (const int files = io::write_trajectory_flow(dir))
    reporter.note("silva: wrote " + std::to_string(files) + " optical flow files into " + (dir / "trajectory").string());
  write_card(dir);
  reporter.result({{"ok", true}, {"run_dir", dir.string()}, {"shards", count}, {"frames", frames}},
                  "merged " + std::to_string(count) + " shards, " + std::to_string(frames) + " frames, into " +
                      (dir / "manifest.json").string());
  return 0;
}
}  // namespace

int run_merge(const MergeRequest& request, const Reporter& reporter) {
  try {
    return merge_shards(request, reporter);
  } catch (const nlohmann::json::exception& e) {  // a field missing or of the wrong type
    throw InputError(request.run_dir.string() + ": a run.shard-i-of-N.json is not what silva generate --shard writes (" +
                     e.what() + ")");
  }
}

}  // namespace silva::app
