#pragma once
/// @file The dataset folder's lifecycle (CONTRACT.md "Output folder"): marker, resume, overwrite.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace silva::io {

/// What the command line allows to happen to an existing run folder.
/// Shard: like Resume, and a fresh folder is fine too, but leftover temp files stay (other
/// shards may be writing them right now; `silva merge` removes them).
enum class FolderMode { Fresh, Resume, Overwrite, Shard };

/// Formats a seed the way folder names and logs show it: %010d.
std::string seed_folder_name(int64_t seed);

/// Reads the config hash and seed recorded in `<dir>/.silva-run.json`; nullopt when absent.
struct RunMarker {
  int64_t seed = 0;          ///< Seed of the run.
  std::string config_hash;   ///< Hash of the resolved config (without output.dir) and the input files' contents.
  std::string config;        ///< The resolved config as TOML (without output.dir); "" in older markers.
};
/// Reads the marker of a run folder; nullopt when the folder has none. Throws InputError if corrupt.
std::optional<RunMarker> read_run_marker(const std::filesystem::path& run_dir);

/// Finds the seed of the single run folder under `output_dir` (for `--resume` without `--seed`).
/// Throws InputError when there is none or more than one, listing them.
int64_t find_resumable_seed(const std::filesystem::path& output_dir);

/// Prepares `<output_dir>/<seed>/` for writing according to `mode` and writes the marker.
/// A folder holding nothing but leftover temp files (a run killed while writing its marker) counts
/// as empty. Fresh: the folder must be absent or empty, else InputError suggesting --resume/--overwrite.
/// Resume: the marker's config hash must match; leftover temp files are deleted.
/// Overwrite: the folder is emptied first (InputError when it is a symbolic link). A different
/// config without Overwrite is InputError. Unwritable paths throw IoError. The marker records
/// `config_text` (what `--resume` reloads) when given. Returns the run folder.
std::filesystem::path prepare_run_folder(const std::filesystem::path& output_dir, int64_t seed,
                                         const std::string& config_hash, FolderMode mode,
                                         const std::string& config_text = "");

}  // namespace silva::io
