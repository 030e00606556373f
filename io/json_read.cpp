#include "io/json_read.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/input_limits.hpp"

namespace silva::io {

std::string read_text_file(const std::filesystem::path& path) {
  return limits::read_input_file(path, "input file");
}

nlohmann::json parse_json_text(const std::string& text, const std::string& where) {
  try {
    limits::check_json_depth(text, where);
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // syntax errors and numbers beyond a double (1e400)
    throw InputError(where + ": not valid JSON (" + e.what() + ")");
  }
}

const nlohmann::json& json_member(const nlohmann::json& obj, const std::string& key, const std::string& where) {
  if (!obj.is_object()) throw InputError(where + ": must be a JSON object");
  const auto it = obj.find(key);
  if (it == obj.end()) throw InputError(where + ": missing key '" + key + "'");
  return *it;
}

double json_number(const nlohmann::json& obj, const std::string& key, const std::string& where) {
  const nlohmann::json& v = json_member(obj, key, where);
  if (!v.is_number() || !std::isfinite(v.get<double>()))
    throw InputError(where + ": '" + key + "' must be a number, got " + limits::quoted_prefix(v.dump()));
  return v.get<double>();
}

long long json_int(const nlohmann::json& obj, const std::string& key, long long lo, long long hi,
                   const std::string& where) {
  const nlohmann::json& v = json_member(obj, key, where);
  if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi)
    throw InputError(where + ": '" + key + "' must be an integer " + std::to_string(lo) + ".." +
                     std::to_string(hi) + ", got " + limits::quoted_prefix(v.dump()));
  return v.get<long long>();
}

std::string json_string(const nlohmann::json& obj, const std::string& key, const std::string& where) {
  const nlohmann::json& v = json_member(obj, key, where);
  if (!v.is_string())
    throw InputError(where + ": '" + key + "' must be a string, got " + limits::quoted_prefix(v.dump()));
  return v.get<std::string>();
}

std::vector<std::vector<double>> json_matrix(const nlohmann::json& obj, const std::string& key, size_t rows,
                                             size_t cols, const std::string& where) {
  const nlohmann::json& v = json_member(obj, key, where);
  const std::string shape = std::to_string(rows) + "x" + std::to_string(cols);
  auto bad = [&] { return InputError(where + ": '" + key + "' must be a " + shape + " nested list of numbers"); };
  if (!v.is_array() || v.size() != rows) throw bad();
  std::vector<std::vector<double>> m(rows, std::vector<double>(cols));
  for (size_t r = 0; r < rows; ++r) {
    if (!v[r].is_array() || v[r].size() != cols) throw bad();
    for (size_t c = 0; c < cols; ++c) {
      if (!v[r][c].is_number() || !std::isfinite(v[r][c].get<double>())) throw bad();
      m[r][c] = v[r][c].get<double>();
    }
  }
  return m;
}

}  // namespace silva::io
