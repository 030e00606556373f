#include "app/cli/output_check.hpp"

#include <unistd.h>

#include "core/error.hpp"

namespace silva::app {

void check_writable_dir(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path existing = fs::absolute(dir, ec);
  while (!existing.empty() && !fs::exists(existing, ec)) {
    if (existing == existing.parent_path()) break;
    existing = existing.parent_path();
  }
  if (!fs::is_directory(existing, ec)) {
    throw IoError("output folder '" + dir.string() + "' cannot be created: '" + existing.string() +
                  "' is not a folder");
  }
  if (::access(existing.c_str(), W_OK | X_OK) != 0) {
    throw IoError("output folder '" + dir.string() + "' is not writable ('" + existing.string() +
                  "' denies writing)");
  }
}

}  // namespace silva::app
