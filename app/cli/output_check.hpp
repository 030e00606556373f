#pragma once
/// @file Checking, without writing anything, that an output folder can be created and written.
#include <filesystem>

namespace silva::app {

/// Throws IoError (exit 3) naming the path when `dir`, or the nearest existing folder above it
/// where it would be created, is not a writable folder.
void check_writable_dir(const std::filesystem::path& dir);

}  // namespace silva::app
