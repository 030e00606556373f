#pragma once
/// @file Helpers shared by the JSON readers: read a file, fetch typed fields with errors that
/// name the file, the place in it and what is allowed.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace silva::io {

/// Reads a whole text file; InputError naming the path if it cannot be opened.
std::string read_text_file(const std::filesystem::path& path);

/// Parses JSON text; InputError "<where>: not valid JSON (...)" on a syntax error.
nlohmann::json parse_json_text(const std::string& text, const std::string& where);

/// The member `key` of object `obj`; InputError "<where>: missing key 'key'" when absent.
const nlohmann::json& json_member(const nlohmann::json& obj, const std::string& key, const std::string& where);

/// A finite number; InputError "<where>: 'key' must be a number" otherwise.
double json_number(const nlohmann::json& obj, const std::string& key, const std::string& where);

/// An integer in [lo, hi]; InputError naming the range otherwise.
long long json_int(const nlohmann::json& obj, const std::string& key, long long lo, long long hi,
                   const std::string& where);

/// A string; InputError otherwise.
std::string json_string(const nlohmann::json& obj, const std::string& key, const std::string& where);

/// A rows x cols nested list of numbers; InputError naming the expected shape otherwise.
std::vector<std::vector<double>> json_matrix(const nlohmann::json& obj, const std::string& key, size_t rows,
                                             size_t cols, const std::string& where);

}  // namespace silva::io
