/// @file The project's source folders and reading their files, for the house-rule tests.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace silva::house {

/// The folders of our own sources (tests/, configs/, docs/ are not source folders).
inline constexpr std::string_view kSourceFolders[] = {"core", "ecs", "components", "world", "render", "raycast", "assets",
                                                      "io", "systems", "web", "pipeline", "bench", "app"};

/// True when `name` is one of kSourceFolders.
bool is_source_folder(std::string_view name);

/// The repository root (SILVA_SOURCE_DIR, compiled in).
std::filesystem::path source_root();

/// Every .cpp and .hpp under root/folder, recursively, sorted; empty when the folder does not exist.
std::vector<std::filesystem::path> source_files(const std::filesystem::path& root, std::string_view folder);

/// The whole file as text (empty when it cannot be read).
std::string read_text(const std::filesystem::path& path);

/// The text split at '\n' (a final line without '\n' counts; a trailing '\n' adds no line).
std::vector<std::string> split_lines(std::string_view text);

/// `path` relative to source_root(), with '/' separators, for messages.
std::string shown(const std::filesystem::path& path);

}  // namespace silva::house
