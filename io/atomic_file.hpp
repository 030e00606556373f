#pragma once
/// @file Atomic file writing (temp file in the same folder + rename) and leftover temp cleanup.
/// A reader never sees a half-written file under its final name: either the old content, the
/// new content, or no file. Files are not fsync'ed (safe against a process crash or kill).
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

namespace silva::io {

/// Suffix appended to a file name while it is being written ("<name>.tmp-silva").
inline constexpr std::string_view kTempSuffix = ".tmp-silva";

/// The temp path write_file_atomic uses for `path`: same folder, name + kTempSuffix.
std::filesystem::path temp_path_for(const std::filesystem::path& path);

/// Writes `bytes` to `path` via its temp file and a rename over the target. On any failure
/// (missing folder, EACCES, ENOSPC, ...) removes the temp file and throws IoError naming the
/// path and the system's reason. Two processes must not write the same path at the same time.
void write_file_atomic(const std::filesystem::path& path, std::span<const uint8_t> bytes);

/// Text overload of write_file_atomic.
void write_file_atomic(const std::filesystem::path& path, std::string_view text);

/// Every leftover temp file (name ending in kTempSuffix) under `dir`, recursively, sorted.
std::vector<std::filesystem::path> list_temp_files(const std::filesystem::path& dir);

/// Deletes every leftover temp file under `dir` (for --resume); returns how many were removed.
/// Throws IoError naming the path when one cannot be removed.
size_t remove_temp_files(const std::filesystem::path& dir);

}  // namespace silva::io
