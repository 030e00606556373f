#include "bench/harness/bench_machine.hpp"

#include <sys/utsname.h>

#include <cctype>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

#include "pipeline/console/version.hpp"
#include "pipeline/config/data_path.hpp"
#include "bench/harness/pipeline_names.hpp"

namespace silva::bench {

namespace {

/// The value after "key" and a colon or '=' on the first line of `path` that starts with `key`.
std::string field(const char* path, const std::string& key) {
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(key, 0) != 0) continue;
    size_t at = line.find_first_of(":=", key.size());
    if (at == std::string::npos) continue;
    std::string v = line.substr(at + 1);
    v.erase(0, v.find_first_not_of(" \t\""));
    while (!v.empty() && (v.back() == '"' || std::isspace(static_cast<unsigned char>(v.back())))) v.pop_back();
    return v;
  }
  return "unknown";
}

/// The first line `cmd` prints (trailing space removed), "" when it prints nothing.
std::string first_line(const std::string& cmd) {
  std::string line;
  if (FILE* p = popen(cmd.c_str(), "r")) {
    char buf[256] = {};
    if (std::fgets(buf, sizeof buf, p)) line = buf;
    pclose(p);
  }
  while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
  return line;
}

/// The source tree's git revision (short hash, "+dirty" when tracked files differ), else the one built in.
std::string source_revision() {
  const std::string git = "git -C '" + data_root().string() + "' ";
  const std::string rev = first_line(git + "rev-parse --short HEAD 2>/dev/null");
  if (rev.empty()) return pipeline::git_revision();
  return rev + (first_line(git + "status --porcelain --untracked-files=no 2>/dev/null").empty() ? "" : "+dirty");
}

}  // namespace

double load_average() {
  std::ifstream in("/proc/loadavg");
  double load = -1;
  in >> load;
  return in ? load : -1;
}

std::string cpu_slug(const std::string& model) {
  std::string lower;
  for (char c : model) lower += char(std::tolower(static_cast<unsigned char>(c)));
  for (const char* noise : {"(r)", "(tm)", " processor", " cpu", "@"}) {
    for (size_t at; (at = lower.find(noise)) != std::string::npos;) lower.erase(at, std::string(noise).size());
  }
  std::string slug;
  for (char c : lower) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '.') slug += c;
    else if (!slug.empty() && slug.back() != '-') slug += '-';
  }
  while (!slug.empty() && slug.back() == '-') slug.pop_back();
  return slug.empty() ? "unknown-cpu" : slug;
}

nlohmann::json machine_description() {
  utsname u{};
  uname(&u);
  double mem_kib = 0;
  std::istringstream(field("/proc/meminfo", "MemTotal")) >> mem_kib;
#if defined(__clang__)
  const std::string compiler = std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  const std::string compiler = std::string("g++ ") + __VERSION__;
#else
  const std::string compiler = "unknown";
#endif
  return {{"cpu", field("/proc/cpuinfo", "model name")},
          {"cores", std::thread::hardware_concurrency()},
          {"memory_gib", mem_kib / (1024.0 * 1024.0)},
          {"os", field("/etc/os-release", "PRETTY_NAME")},
          {"kernel", std::string(u.sysname) + " " + u.release + " " + u.machine},
          {"compiler", compiler},
          {"git_revision", source_revision()},
          {"load_average_start", load_average()}};
}

}  // namespace silva::bench
