#pragma once
/// @file Error types that map to the CLI's exit codes (CONTRACT.md: 2 bad input, 3 I/O failure).
#include <stdexcept>
#include <string>

namespace silva {

/// Bad input (arguments, config, pose file, asset, manifest, output-folder state): exit code 2.
/// The message is one line naming the file, key or value and what is allowed.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// I/O failure (unwritable path, disk full): exit code 3. The message names the path.
struct IoError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace silva
