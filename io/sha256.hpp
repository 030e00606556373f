#pragma once
/// @file SHA-256 digests of files recorded in manifest.json (OpenSSL libcrypto).
#include <filesystem>
#include <string>

namespace silva::io {

/// Lower-case hex SHA-256 of a file's bytes. Throws InputError when it cannot be read.
std::string sha256_file(const std::filesystem::path& path);

/// Lower-case hex SHA-256 of a byte string.
std::string sha256_hex(const std::string& bytes);

}  // namespace silva::io
