#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include "core/error.hpp"

namespace silva::io {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const fs::path& path, const char* what, int err) {
  throw IoError("cannot write " + path.string() + ": " + what + ": " + std::strerror(err));
}

/// Writes all of `bytes` to `fd`, retrying short writes and EINTR; returns 0 or an errno.
int write_all(int fd, std::span<const uint8_t> bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    done += size_t(n);
  }
  return 0;
}

bool is_temp_name(const fs::path& p) {
  const std::string name = p.filename().string();
  return name.size() > kTempSuffix.size() && name.ends_with(kTempSuffix);
}

}  // namespace

fs::path temp_path_for(const fs::path& path) {
  fs::path tmp = path;
  tmp += std::string(kTempSuffix);
  return tmp;
}

void write_file_atomic(const fs::path& path, std::span<const uint8_t> bytes) {
  const fs::path tmp = temp_path_for(path);
  // A new file of our own, never through a link: a leftover temp name (a killed run's file, or a
  // link planted to redirect the write) is unlinked, which removes the name, not its target.
  constexpr int kFlags = O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC;
  int fd = ::open(tmp.c_str(), kFlags, 0644);
  if (fd < 0 && errno == EEXIST && ::unlink(tmp.c_str()) == 0) fd = ::open(tmp.c_str(), kFlags, 0644);
  if (fd < 0) fail(path, "cannot create temp file", errno);
  int err = write_all(fd, bytes);
  if (::close(fd) != 0 && err == 0) err = errno;
  if (err == 0 && std::rename(tmp.c_str(), path.c_str()) != 0) err = errno;
  if (err != 0) {
    ::unlink(tmp.c_str());
    fail(path, "write failed", err);
  }
}

void write_file_atomic(const fs::path& path, std::string_view text) {
  write_file_atomic(path, std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(text.data()), text.size()));
}

std::vector<fs::path> list_temp_files(const fs::path& dir) {
  std::vector<fs::path> found;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec))
    if (is_temp_name(it->path()) && !it->is_directory(ec)) found.push_back(it->path());
  if (ec) throw IoError("cannot list " + dir.string() + ": " + ec.message());
  std::sort(found.begin(), found.end());
  return found;
}

size_t remove_temp_files(const fs::path& dir) {
  const std::vector<fs::path> files = list_temp_files(dir);
  for (const fs::path& p : files) {
    std::error_code ec;
    fs::remove(p, ec);
    if (ec) throw IoError("cannot remove leftover temp file " + p.string() + ": " + ec.message());
  }
  return files.size();
}

}  // namespace silva::io
