#include "pipeline/config/data_path.hpp"

#include <cstdlib>

namespace silva::pipeline {

std::filesystem::path data_root() {
  const char* env = std::getenv("SILVA_DATA");
  if (env != nullptr && *env != '\0') return std::filesystem::path(env);
  return std::filesystem::path(SILVA_DATA_DIR);
}

std::filesystem::path data_path(const std::string& relative) { return data_root() / relative; }

}  // namespace silva::pipeline
