#pragma once
/// @file Helpers for tests that drive the built `silva` binary (SILVA_BINARY) as a child
/// process: run it, start it and kill it, and compare the files of two run folders.
#include <sys/types.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace silva::test {

/// What one `silva ...` process printed and how it ended.
struct ProcessResult {
  int code = -1;    ///< Exit status, or 128 + signal number when killed.
  std::string out;  ///< Everything on stdout.
  std::string err;  ///< Everything on stderr.
};

/// A running `silva` child whose stdout/stderr go to files in a scratch folder.
struct ChildProcess {
  pid_t pid = -1;                ///< Process id.
  std::filesystem::path out;     ///< File receiving stdout.
  std::filesystem::path err;     ///< File receiving stderr.
};

/// Starts `silva args...` with stdout/stderr redirected into files under `scratch`; with `traced`
/// the child stops at its start under this process's ptrace (see stop_after_lock).
ChildProcess start_silva(const std::vector<std::string>& args, const std::filesystem::path& scratch,
                         bool traced = false);

/// Runs a child started with `traced` until one of its flock() calls succeeds (it took its run-folder
/// lock) and leaves it stopped there, holding the lock; false when it ended first.
bool stop_after_lock(const ChildProcess& child);

/// Lets a traced child run on, no longer traced.
void release_traced(const ChildProcess& child);

/// Waits for `child` and collects its exit status and output.
ProcessResult wait_silva(const ChildProcess& child);

/// Runs `silva args...` to completion (output collected via files under `scratch`).
ProcessResult run_silva(const std::vector<std::string>& args, const std::filesystem::path& scratch);

/// Every regular file below `dir` (hidden ones included) by relative path, with its bytes;
/// unless `with_run_records`, files named run*.json (run.json, run.shard-*.json) are left out.
std::map<std::string, std::string> folder_files(const std::filesystem::path& dir, bool with_run_records = false);

/// "" when `a` and `b` hold the same files with the same bytes, else a line naming the files
/// only one holds and the first few that differ.
std::string file_differences(const std::map<std::string, std::string>& a, const std::map<std::string, std::string>& b);

/// Every output type (output.types as a TOML list).
inline constexpr const char* kAllTypes =
    R"(["rgb","semantic","semantic_color","instance","depth","depth_exr","normal","depth_preview"])";
/// The label output types only: no rgb, so no shadow map and shading (fast).
inline constexpr const char* kLabelTypes = R"(["semantic","instance","depth","depth_exr","normal"])";

/// Arguments for a tiny, fast run of seed `seed` into `out`: 64x48, 1 autopilot point x 3 yaws
/// + 2 random poses, a 128 m world, far plane 40 m, the given output types (a TOML list).
std::vector<std::string> tiny_run_args(const std::filesystem::path& out, int64_t seed, const char* types = kLabelTypes);

/// A fresh, empty scratch folder for the running test (under ::testing::TempDir()), removed at
/// the end of a test program whose tests all passed.
std::filesystem::path fresh_test_dir();

/// Reads a whole file ("" when it cannot be read).
std::string read_file(const std::filesystem::path& path);

/// The lines of `text` (without the newlines; a trailing newline adds no empty line).
std::vector<std::string> lines_of(const std::string& text);

}  // namespace silva::test
