// `silva export` after the CLI checks: each format is written into a hidden partial folder and moved
// into place only when complete, so an interrupted or failed export never replaces a good one.
#include <algorithm>
#include <cstdio>
#include <optional>
#include <system_error>

#include "app/commands/export/export_command.hpp"
#include "pipeline/console/progress.hpp"
#include "core/error.hpp"
#include "core/stopwatch.hpp"

namespace silva::app {

namespace fs = std::filesystem;

namespace {

/// True when `dir` exists and is not an empty folder.
bool holds_something(const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) return false;
  return !fs::is_directory(dir, ec) || !fs::is_empty(dir, ec);
}

void remove_folder(const fs::path& dir) {
  std::error_code ec;
  fs::remove_all(dir, ec);
  if (ec) throw IoError("cannot remove " + dir.string() + ": " + ec.message());
}

/// True when `inner` is `outer` or lies below it (both made absolute, links resolved where they exist).
bool within(const fs::path& inner, const fs::path& outer) {
  const fs::path a = fs::weakly_canonical(fs::absolute(inner)), b = fs::weakly_canonical(fs::absolute(outer));
  auto i = a.begin();
  for (auto o = b.begin(); o != b.end(); ++o, ++i)
    if (i == a.end() || *i != *o) return false;
  return true;
}

}  // namespace

void check_export_location(const fs::path& run_dir, const fs::path& out_dir, const std::vector<io::ExportFormat>& formats) {
  for (io::ExportFormat format : formats) {
    const fs::path target = out_dir / io::export_format_name(format);
    if (within(run_dir, target))
      throw InputError(target.string() + ": the export would replace the dataset " + run_dir.string() +
                       " it reads; choose an --out outside it");
    if (within(target, run_dir) && !within(target, run_dir / "export"))
      throw InputError(out_dir.string() + ": inside the dataset " + run_dir.string() +
                       "; exports go to " + (run_dir / "export").string() + " or outside the dataset");
  }
}

nlohmann::json export_formats(const io::Dataset& dataset, const std::vector<io::ExportFormat>& formats,
                              const fs::path& out_dir, bool overwrite, const io::ExportOptions& options) {
  for (io::ExportFormat format : formats) {
    const fs::path target = out_dir / io::export_format_name(format);
    if (!overwrite && holds_something(target))
      throw InputError(target.string() + ": already exists; pass --overwrite to replace it");
  }
  nlohmann::json written = nlohmann::json::array();
  for (io::ExportFormat format : formats) {
    const Stopwatch clock;
    const std::string& name = io::export_format_name(format);
    const fs::path target = out_dir / name, partial = out_dir / ("." + name + ".partial");
    remove_folder(partial);
    io::create_folder(partial);
    io::export_dataset(dataset, format, partial, options);
    remove_folder(target);
    std::error_code ec;
    fs::rename(partial, target, ec);
    if (ec) throw IoError("cannot move " + partial.string() + " to " + target.string() + ": " + ec.message());
    written.push_back({{"format", name}, {"dir", target.string()}, {"seconds", clock.seconds()}});
  }
  return written;
}

int run_export(const ExportRequest& request, const Reporter& reporter) {
  const io::Dataset dataset = io::open_dataset(request.run_dir);
  std::vector<io::ExportFormat> formats = request.formats;
  if (request.all)
    for (size_t i = 0; i < io::export_format_names().size(); ++i) {
      const auto format = io::ExportFormat(i);
      if (format == io::ExportFormat::SemanticKitti && !dataset.has("lidar")) continue;
      if (format == io::ExportFormat::Euroc && !dataset.has_sequence("trajectory")) continue;
      if (format == io::ExportFormat::Tartanair &&
          !(dataset.has("rgb") && dataset.has("semantic") && (dataset.has("depth") || dataset.has("depth_exr"))))
        continue;
      if (std::find(formats.begin(), formats.end(), format) == formats.end()) formats.push_back(format);
    }
  check_export_location(request.run_dir, request.out_dir, formats);
  const Stopwatch clock;
  io::ExportOptions options = request.options;
  std::optional<Progress> progress;  // the streaming export (rosbag2) reports frame by frame, from 0 at its start
  options.progress = [&](size_t done, size_t total) {
    if (!progress) progress.emplace(reporter, int(total), "frames");
    if (done > 0) progress->update(int(done));
  };
  const nlohmann::json written = export_formats(dataset, formats, request.out_dir, request.overwrite, options);
  if (progress) progress->finish();
  std::string line;
  for (const auto& w : written) {
    char buf[64];
    std::snprintf(buf, sizeof buf, " (%.2f s)", w["seconds"].get<double>());
    line += (line.empty() ? "" : ", ") + w["dir"].get<std::string>() + buf;
  }
  reporter.result({{"ok", true}, {"run_dir", request.run_dir.string()}, {"frames", dataset.frames.size()},
                   {"exports", written}, {"wall_s", clock.seconds()}},
                  "exported " + std::to_string(dataset.frames.size()) + " frames to " + line);
  return 0;
}

}  // namespace silva::app
