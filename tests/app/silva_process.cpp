#include "silva_process.hpp"

#include "tests/common/scratch_dirs.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/ptrace.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>

namespace silva::test {

namespace fs = std::filesystem;

ChildProcess start_silva(const std::vector<std::string>& args, const fs::path& scratch, bool traced) {
  static int counter = 0;
  ChildProcess child;
  const std::string tag = std::to_string(counter++);
  child.out = scratch / ("stdout." + tag);
  child.err = scratch / ("stderr." + tag);
  std::vector<std::string> argv_store = {SILVA_BINARY};
  argv_store.insert(argv_store.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_store) argv.push_back(a.data());
  argv.push_back(nullptr);
  child.pid = fork();
  if (child.pid == 0) {
    const int out = ::open(child.out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(child.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0) _exit(126);
    ::dup2(out, STDOUT_FILENO);
    ::dup2(err, STDERR_FILENO);
    if (traced && ::ptrace(PTRACE_TRACEME, 0, nullptr, nullptr) != 0) _exit(125);
    ::execv(argv[0], argv.data());
    _exit(127);
  }
  return child;
}

bool stop_after_lock(const ChildProcess& child) {
  int status = 0;
  if (::waitpid(child.pid, &status, 0) != child.pid || !WIFSTOPPED(status)) return false;  // the stop at exec
  ::ptrace(PTRACE_SETOPTIONS, child.pid, nullptr, PTRACE_O_TRACESYSGOOD | PTRACE_O_EXITKILL);
  uint64_t call = 0;  // the system call the child is in
  long signal = 0;    // a signal to pass on
  for (;;) {
    if (::ptrace(PTRACE_SYSCALL, child.pid, nullptr, signal) != 0) return false;
    if (::waitpid(child.pid, &status, 0) != child.pid || !WIFSTOPPED(status)) return false;
    signal = 0;
    if (WSTOPSIG(status) != (SIGTRAP | 0x80)) {  // a signal, not a system call stop
      signal = WSTOPSIG(status);
      continue;
    }
    __ptrace_syscall_info info{};
    if (::ptrace(PTRACE_GET_SYSCALL_INFO, child.pid, sizeof info, &info) <= 0) return false;
    if (info.op == PTRACE_SYSCALL_INFO_ENTRY) call = info.entry.nr;
    if (info.op == PTRACE_SYSCALL_INFO_EXIT && call == SYS_flock && info.exit.rval == 0) return true;
  }
}

void release_traced(const ChildProcess& child) { ::ptrace(PTRACE_DETACH, child.pid, nullptr, nullptr); }

ProcessResult wait_silva(const ChildProcess& child) {
  ProcessResult r;
  int status = 0;
  if (::waitpid(child.pid, &status, 0) == child.pid)
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = read_file(child.out);
  r.err = read_file(child.err);
  return r;
}

ProcessResult run_silva(const std::vector<std::string>& args, const fs::path& scratch) {
  return wait_silva(start_silva(args, scratch));
}

std::map<std::string, std::string> folder_files(const fs::path& dir, bool with_run_records) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    const std::string name = entry.path().filename().string();
    if (!with_run_records && name.rfind("run", 0) == 0 && entry.path().extension() == ".json") continue;
    files[fs::relative(entry.path(), dir).string()] = read_file(entry.path());
  }
  return files;
}

std::string file_differences(const std::map<std::string, std::string>& a, const std::map<std::string, std::string>& b) {
  std::string diff;
  int shown = 0;
  auto note = [&](const std::string& what) {
    if (shown++ < 8) diff += what + "; ";
  };
  for (const auto& [name, bytes] : a) {
    const auto it = b.find(name);
    if (it == b.end()) note("only in the first: " + name);
    else if (it->second != bytes) note("bytes differ: " + name);
  }
  for (const auto& [name, bytes] : b)
    if (!a.count(name)) note("only in the second: " + name);
  if (shown > 8) diff += std::to_string(shown - 8) + " more";
  return diff;
}

std::vector<std::string> tiny_run_args(const fs::path& out, int64_t seed, const char* types) {
  return {"generate", "--seed", std::to_string(seed), "--out", out.string(),
          "--set", "output.resolution=64x48", "--set", "captures.autopilot_points=1",
          "--set", "captures.random_count=2", "--set", "world.extent=128",
          "--set", "world.render_distance=48", "--set", "trail.control_points=6",
          "--set", "camera.far=40", "--set", std::string("output.types=") + types};
}

fs::path fresh_test_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(::testing::TempDir()) /
                       ("silva_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
                        std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  remove_when_passed(dir);
  return dir;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

}  // namespace silva::test
