#include "core/input_limits.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/error.hpp"

namespace silva::limits {

int json_nesting_depth(std::string_view text) {
  int depth = 0, deepest = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
      if (deepest > kMaxJsonDepth) return deepest;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return deepest;
}

void check_json_depth(std::string_view text, const std::string& where) {
  if (json_nesting_depth(text) > kMaxJsonDepth)
    throw InputError(where + ": JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
}

std::string read_input_file(const std::filesystem::path& path, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) throw InputError(what + " " + path.string() + ": not found");
  if (!fs::is_regular_file(status)) throw InputError(what + " " + path.string() + ": not a regular file");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw InputError(what + " " + path.string() + ": cannot be read (" + ec.message() + ")");
  if (size > kMaxInputFileBytes)
    throw InputError(what + " " + path.string() + ": " + std::to_string(size) + " bytes, larger than the limit of " +
                     std::to_string(kMaxInputFileBytes) + " bytes");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  if (in) s << in.rdbuf();
  if (!in || in.bad()) throw InputError(what + " " + path.string() + ": cannot be read");
  return s.str();
}

std::string quoted_prefix(std::string_view text) {
  if (text.size() <= kMaxQuotedChars) return std::string(text);
  return std::string(text.substr(0, kMaxQuotedChars)) + "...";
}

}  // namespace silva::limits
