#include "io/run_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>

#include "core/error.hpp"

namespace silva::io {

namespace fs = std::filesystem;

namespace {
/// The PID holding an flock on inode `ino` per /proc/locks, or "" when it cannot be told.
std::string lock_holder(ino_t ino) {
  std::ifstream locks("/proc/locks");
  std::string line;
  const std::string suffix = ":" + std::to_string(ino);
  while (std::getline(locks, line)) {
    std::istringstream fields(line);
    std::string index, kind, mode, access, pid, device;
    fields >> index >> kind;
    if (kind == "->") fields >> kind;  // a waiter, listed under the holder
    fields >> mode >> access >> pid >> device;
    if (kind == "FLOCK" && device.size() > suffix.size() && device.ends_with(suffix)) return pid;
  }
  return "";
}
}  // namespace

RunLock::RunLock(RunLock&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}

RunLock& RunLock::operator=(RunLock&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = std::exchange(other.fd_, -1);
  }
  return *this;
}

RunLock::~RunLock() {
  if (fd_ >= 0) ::close(fd_);
}

RunLock lock_run_folder(const fs::path& run_dir, bool exclusive) {
  std::error_code ec;
  fs::create_directories(run_dir, ec);
  if (ec) throw IoError("cannot create output folder " + run_dir.string() + ": " + ec.message());
  RunLock lock;
  lock.fd_ = ::open(run_dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (lock.fd_ < 0) throw IoError("cannot open output folder " + run_dir.string() + ": " + std::strerror(errno));
  if (::flock(lock.fd_, (exclusive ? LOCK_EX : LOCK_SH) | LOCK_NB) == 0) return lock;
  const int err = errno;
  if (err != EWOULDBLOCK) throw IoError("cannot lock " + run_dir.string() + ": " + std::strerror(err));
  struct stat st {};
  ::fstat(lock.fd_, &st);
  const std::string pid = lock_holder(st.st_ino);
  throw InputError(run_dir.string() + " is in use by another silva process" + (pid.empty() ? "" : " (PID " + pid + ")") +
                   "; wait for it to finish or stop it, or choose another --out");
}

}  // namespace silva::io
