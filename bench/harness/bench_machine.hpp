#pragma once
/// @file The machine a benchmark ran on (CPU, cores, memory, OS, compiler, git revision, load).
#include <string>

#include <nlohmann/json.hpp>

namespace silva::bench {

/// {"cpu", "cores", "memory_gib", "os", "kernel", "compiler", "git_revision", "load_average"}.
nlohmann::json machine_description();

/// The CPU model as a file-name slug: "AMD EPYC 7B13 64-Core Processor" -> "amd-epyc-7b13-64-core".
std::string cpu_slug(const std::string& model);

/// The 1-minute load average (/proc/loadavg), or -1 when unknown.
double load_average();

}  // namespace silva::bench
